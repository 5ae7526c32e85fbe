#include "saltus/studies/convergence_study.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

#include "saltus/base/text_format.h"

namespace saltus {

Motion disturb_keyframe_times(const Motion& motion, double amplitude, unsigned seed,
                              double min_gap_s) {
  Motion out = motion;
  out.spline.reset();  // a stored spline belongs to the old times
  const int n = static_cast<int>(motion.keyframes.size());
  if (n < 3 || amplitude == 0.0) return out;
  const double duration = motion.flight_time();
  // The raw engine output is the same on every platform (distributions are not).
  std::mt19937 engine(seed);
  for (int i = 1; i + 1 < n; ++i) {
    const double sign = (engine() & 1u) ? 1.0 : -1.0;
    double t = motion.keyframes[i].time + sign * amplitude;
    t = std::max(t, out.keyframes[i - 1].time + min_gap_s);
    t = std::min(t, duration - (n - 1 - i) * min_gap_s);
    out.keyframes[i].time = t;
  }
  return out;
}

std::vector<StudyCase> convergence_study_cases(const std::vector<LabelledMotion>& motions,
                                               const ConvergenceStudyOptions& options) {
  std::vector<std::pair<Formulation, double>> formulations{{Formulation::kRelaxed, 0.0}};
  for (double e : options.epsilons)
    formulations.emplace_back(Formulation::kStrict, e);
  std::vector<std::pair<std::string, double>> masses;
  bool nominal = false;
  for (const std::string& segment : options.mass_segments)
    for (double error : options.mass_errors) {
      if (error == 0.0) {
        if (!nominal) masses.emplace_back("all", 0.0);
        nominal = true;
      } else {
        masses.emplace_back(segment, error);
      }
    }
  std::vector<StudyCase> cases;
  for (const LabelledMotion& m : motions)
    for (const auto& [formulation, epsilon] : formulations)
      for (const auto& [segment, error] : masses)
        for (double timing : options.timing_errors) {
          StudyCase c;
          c.motion = m.label;
          c.formulation = formulation;
          c.epsilon = epsilon;
          c.mass_segment = segment;
          c.mass_error = error;
          c.timing_error_s = timing;
          cases.push_back(c);
        }
  return cases;
}

StudyOutcome run_study_case(const LabelledMotion& motion, const StudyCase& study_case,
                            const ConvergenceStudyOptions& options) {
  const Motion disturbed =
      disturb_keyframe_times(motion.file.motion, study_case.timing_error_s, options.seed);
  BodyModel model = motion.file.model;
  if (study_case.mass_error != 0.0) {
    const std::string segment = study_case.mass_segment == "all" ? "" : study_case.mass_segment;
    model = scale_segment_mass(model, segment, 1.0 + study_case.mass_error);
  }
  OptimizeOptions optimize = options.optimize;
  optimize.nlp.formulation = study_case.formulation;
  if (study_case.formulation == Formulation::kStrict) {
    optimize.nlp.epsilon = study_case.epsilon;
    optimize.solver.feasibility_checkpoints = options.strict_checkpoints;
  }
  const OptimizationResult r = optimize_motion(disturbed, model, optimize);
  StudyOutcome o;
  static_cast<RunSummary&>(o) = summarize_run(disturbed, r);
  o.study_case = study_case;
  return o;
}

StudyOutcome unfinished_outcome(const StudyCase& study_case, const std::string& status,
                                double seconds) {
  StudyOutcome o;
  o.study_case = study_case;
  o.status = status;
  o.seconds = seconds;
  return o;
}

std::string formulation_label(const StudyCase& study_case) {
  if (study_case.formulation == Formulation::kRelaxed) return "relaxed";
  return format_number("strict ε=%g", study_case.epsilon);
}

}  // namespace saltus

namespace saltus {

std::string study_case_label(const StudyCase& c) {
  std::string mass = c.mass_error == 0.0 ? std::string("0 %")
                                         : format_number("%+.0f %%", 100.0 * c.mass_error) + " (" +
                                               c.mass_segment + ")";
  return c.motion + " " + formulation_label(c) + ", mass " + mass + ", timing " +
         (c.timing_error_s == 0.0 ? std::string("0 s")
                                  : format_number("±%.2f s", c.timing_error_s));
}

}  // namespace saltus
