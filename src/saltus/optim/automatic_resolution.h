#pragma once
/// @file
/// The automatic resolution's rules (`--knots-per-interval auto`, docs/optimizer.md): the first
/// level's knot spans per keyframe interval from how far the body turns in it, and each
/// refinement from where the dense check finds the residual. Deterministic: the same input, the
/// same knots.

#include <vector>

#include "saltus/body/body_model.h"
#include "saltus/evaluation/force_metrics.h"
#include "saltus/motion/motion.h"

namespace saltus {

/// The rules of the automatic resolution, deterministic: the same input, the same knots.
struct AutomaticResolution {
  /// First guess: each keyframe interval split so that no segment, turning at its fastest rate
  /// on the interval, would turn in the world by more than this in one span (rad), ... Fine
  /// enough that the first level usually ends within ~10× of target_force, where one
  /// refinement reaches it (docs/performance.md, "Fewer levels").
  double turn_per_span = 1.6;  // 92°
  /// ... and no span is longer than this (s).
  double max_span = 0.26;
  /// Stop once the true average root force (the dense check) is at most this (N) and the
  /// motion's own free flight lands within max_landing_drift_deg of it...
  double target_force = 0.25;
  /// ... degrees: the whole-body orientation at landing of the free flight from the optimised
  /// motion's own take-off state with its joint movements, against the motion's (what
  /// `saltus simulate optimized.motion.json` reports). A small absolute root force is not enough:
  /// on a light athlete or a twisting skill 0.2-0.4 N turned into 34-83° (docs/optimizer.md,
  /// "Landing drift").
  double max_landing_drift_deg = 3.0;
  /// ... or a refinement cut it by less than this fraction (more knots stop paying).
  double min_gain = 0.3;
  /// A refinement splits each interval's spans by the factor its own mean squared wrench asks
  /// for, assuming the average root force falls like the span length to this power (fitted on
  /// the bundled motions: docs/performance.md, "Fewer levels").
  double convergence_order = 2.5;
  int max_spans_per_interval = 8;
  int max_refinements = 2;
  /// A level that may be refined only needs to say where its residual lives: it stops at this
  /// relative objective change instead of the final one (and, if it then meets target_force,
  /// is finished at the final one, warm-started).
  double coarse_objective_change = 1e-2;
};

/// The first guess: interval i split into enough spans that no segment, turning at its fastest
/// rate on the interval, would turn by more than rules.turn_per_span in one span, and no span is
/// longer than rules.max_span (1 to rules.max_spans_per_interval spans).
std::vector<int> first_subdivisions(const Motion& motion, const BodyModel& model,
                                    const AutomaticResolution& rules);

/// Splits interval i's spans by ⌈(m_i / (6·target²))^(1/(2p))⌉, m_i its mean squared wrench
/// (residual[i] over the interval's length) and p rules.convergence_order: the factor that brings
/// its own average root force to the target if the force falls like h^p; never fewer spans, at
/// most rules.max_spans_per_interval. False when nothing can be refined further.
bool refine(std::vector<int>& subdivisions, const std::vector<double>& residual,
            const std::vector<double>& keyframe_times, const AutomaticResolution& rules);

}  // namespace saltus
