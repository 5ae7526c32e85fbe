#pragma once
/// @file
/// The sizes of a root wrench that people read: the resultant force |F| and moment |M| over time
/// (the paper's Figs. 4 and 5 plot |F|), and a force as a share of body weight, which is how
/// residual forces are judged in biomechanics (OpenSim's residual-reduction guidelines: residual
/// forces below a few per cent of body weight).

#include <vector>

#include "saltus/body/body_model.h"
#include "saltus/evaluation/sampling.h"

namespace saltus {

/// |F1..F3| of one wrench (force first), N.
double force_magnitude(const Vector6d& wrench);
/// |F4..F6| of one wrench, N·m.
double moment_magnitude(const Vector6d& wrench);

/// |F1..F3| and |F4..F6| of the root wrench at every sample (root frame, about the root origin).
std::vector<double> root_force_magnitudes(const std::vector<SampleRecord>& samples);
std::vector<double> root_moment_magnitudes(const std::vector<SampleRecord>& samples);

/// The body's weight m·|g|, N (total mass of the model, g of the dynamics).
double body_weight(const BodyModel& model);
/// A force as a percentage of the model's body weight (0 for a massless model).
double percent_of_body_weight(double force_N, const BodyModel& model);

}  // namespace saltus
