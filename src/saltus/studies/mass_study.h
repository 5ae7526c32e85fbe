#pragma once
/// @file
/// The mass study (§6.1, Fig. 8): the same motion optimised with two sets of mass parameters,
/// and the loads at chosen joints over time. Its files are formats/mass_files.h.

#include <string>
#include <vector>

#include "saltus/motion/motion.h"
#include "saltus/optim/optimize.h"

namespace saltus {

/// The mass study (§6.1): the motion optimised once per model; joint loads of the optimised
/// motions over time, against the loads the interpolated input needs on the same model.
struct MassStudyOptions {
  std::vector<std::string> scaled_segments{"thigh_l", "thigh_r"};
  double factor = 1.5;  ///< mass and inertia multiplier of the scaled segments
  std::vector<std::string> load_segments{"thigh_r", "upper_arm_r"};  ///< whose joint loads
  OptimizeOptions optimize;
  /// Optimise at the paper's resolution (knots at the keyframes, no keyframe prior) instead of
  /// `optimize` as given. Off by default: at that resolution M2's root force stays near 2 N and
  /// the joints pay for the rest (peaks 10-40x the input's; docs/studies.md, "Mass study").
  bool paper_protocol = false;
};

struct MassStudyRun {
  std::string label;  ///< "table2" or e.g. "thigh_l+thigh_r x1.5"
  BodyModel model;
  OptimizationResult result;  ///< result.before: the interpolated input on this model
};

struct MassStudyResult {
  std::vector<MassStudyRun> runs;  ///< the given model first, then the scaled one
  std::vector<std::string> load_segments;
};

MassStudyResult run_mass_study(const MotionFile& file, const MassStudyOptions& options);

}  // namespace saltus
