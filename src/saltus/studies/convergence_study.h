#pragma once
/// @file
/// The convergence study (§3.4, the paper's central claim) as library calls: relaxed versus
/// strict models under mass-parameter error and keyframe-timing error. Behind
/// `saltus study convergence` and the reproduction report; its files are
/// formats/convergence_files.h.

#include <string>
#include <vector>

#include "saltus/motion/motion.h"
#include "saltus/optim/optimize.h"
#include "saltus/studies/run_summary.h"

namespace saltus {

/// A motion file's contents with a short label for tables ("M1", "dive-5m", ...).
struct LabelledMotion {
  std::string label;
  MotionFile file;
};

/// One optimisation of the convergence study.
struct StudyCase {
  std::string motion;  ///< LabelledMotion::label
  Formulation formulation = Formulation::kRelaxed;
  double epsilon = 0.0;         ///< strict model's bound, N or N·m; 0 for relaxed
  std::string mass_segment;     ///< "all" or a segment name
  double mass_error = 0.0;      ///< relative: −0.2 = masses and inertias 20 % too small
  double timing_error_s = 0.0;  ///< amplitude of the keyframe-time disturbance
};

/// A case and the summary of its optimisation (run on the disturbed keyframes and model).
struct StudyOutcome : RunSummary {
  StudyCase study_case;
};

/// When a strict run of a study is given up (SolverOptions::feasibility_checkpoints): by 80
/// iterations its constraint violation must have been below 20 (N, N·m or keyframe
/// tolerances), by 120 below 10, by 150 below 5. Set, with a margin, from when the strict runs
/// of the full report's study that solved came below each (docs/studies.md; docs/optimizer.md,
/// "Measurement history").
inline const std::vector<FeasibilityCheckpoint> kStrictStudyCheckpoints{
    {80, 20.0}, {120, 10.0}, {150, 5.0}};

struct ConvergenceStudyOptions {
  std::vector<double> epsilons{10, 50, 100, 500};  ///< strict runs; the relaxed run is always made
  std::vector<double> mass_errors{-0.2, -0.1, 0.0, 0.1, 0.2};
  std::vector<std::string> mass_segments{"all"};  ///< "all" or segment names
  std::vector<double> timing_errors{0.0, 0.05, 0.1};
  unsigned seed = 1;  ///< of the keyframe-time disturbance (same seed, same study)
  /// Feasibility checkpoints of the strict runs (empty: each runs to its iteration limit).
  std::vector<FeasibilityCheckpoint> strict_checkpoints = kStrictStudyCheckpoints;
  /// Everything else (samples, iterations, K, ...): the paper's protocol unless changed.
  OptimizeOptions optimize = paper_protocol_options();
};

/// The motion with each interior keyframe time moved by +amplitude or −amplitude (signs drawn
/// from `seed`), then pushed apart where needed so consecutive times stay >= `min_gap_s` apart
/// and inside (0, T). The poses stay where they are: only their times are wrong.
Motion disturb_keyframe_times(const Motion& motion, double amplitude, unsigned seed,
                              double min_gap_s = 0.05);

/// Every case of the factorial design, motion by motion (formulations × mass segments × mass
/// errors × timing errors; the 0 mass error is run once, not once per segment).
std::vector<StudyCase> convergence_study_cases(const std::vector<LabelledMotion>& motions,
                                               const ConvergenceStudyOptions& options);

/// Runs one case: the motion with its times disturbed, the model with its masses scaled.
StudyOutcome run_study_case(const LabelledMotion& motion, const StudyCase& study_case,
                            const ConvergenceStudyOptions& options);

/// The outcome recorded for a case whose process did not finish (status "crashed" or
/// "timed_out"): not solved, no figures.
StudyOutcome unfinished_outcome(const StudyCase& study_case, const std::string& status,
                                double seconds);

/// "relaxed" or "strict ε=50".
std::string formulation_label(const StudyCase& study_case);

/// One line per case: "M3 strict ε=50, mass -20 % (all), timing ±0.05 s".
std::string study_case_label(const StudyCase& study_case);

}  // namespace saltus
