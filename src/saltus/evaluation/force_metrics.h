#pragma once
/// @file
/// The root-force figures Saltus reports about a sampled motion: the paper's objective and
/// "average force acting on the root" (Table 1), RMS and peak force and moment.

#include <vector>

#include "saltus/evaluation/sampling.h"

namespace saltus {

/// Root-force figures over a sampled motion (trapezoidal rule in time).
struct ForceMetrics {
  double objective = 0.0;       ///< J = (1/T) ∫ Σ F_i² dt (paper eq. 1), N² mixing N·m²
  double avg_root_force = 0.0;  ///< sqrt(J / 6): the paper's "average force acting on the root"
  double rms_force_N = 0.0;     ///< sqrt((1/T) ∫ |F_1..3|² dt)
  double rms_moment_Nm = 0.0;   ///< sqrt((1/T) ∫ |F_4..6|² dt)
  double max_force_N = 0.0;     ///< max over samples of |F_1..3|
  double max_moment_Nm = 0.0;   ///< max over samples of |F_4..6|
};

ForceMetrics force_metrics(const std::vector<SampleRecord>& samples);

}  // namespace saltus
