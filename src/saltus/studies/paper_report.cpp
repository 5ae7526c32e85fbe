#include "saltus/studies/paper_report.h"

#include <algorithm>

#include "saltus/base/text_format.h"

namespace saltus {

PaperReport run_paper_report(const std::vector<LabelledMotion>& skills,
                             const std::vector<LabelledMotion>& dives,
                             const PaperReportOptions& options) {
  auto log = [&](const std::string& line) {
    if (options.log) options.log(line);
  };
  PaperReport report;
  for (const LabelledMotion& skill : skills) {
    PaperSkillRun run;
    run.motion = skill;
    run.options = options.optimize;
    run.options.automatic_resolution = false;  // the paper's resolution: knots at the keyframes
    run.options.nlp.knots_per_interval = 1;
    run.paper_resolution = optimize_motion(skill.file.motion, skill.file.model, run.options);
    log(skill.label + ": " + run.paper_resolution.solve.status + ", " +
        format_number("%.3g", run.paper_resolution.before.metrics.avg_root_force) + " -> " +
        format_number("%.3g N", run.paper_resolution.after.metrics.avg_root_force));
    if (!options.quick) {
      OptimizeOptions k3 = options.optimize;
      k3.automatic_resolution = false;
      k3.nlp.knots_per_interval = 3;
      run.refined = optimize_motion(skill.file.motion, skill.file.model, k3);
      log(skill.label + ", K = 3: " + run.refined->solve.status + ", " +
          format_number("%.3g N", run.refined->after.metrics.avg_root_force));
    }
    report.skills.push_back(std::move(run));
  }

  // The 5 m dive (§6.2): keyframe times before and after (Fig. 9).
  for (const LabelledMotion& dive : dives) {
    PaperDiveRun run;
    run.motion = dive;
    run.options = options.optimize;
    run.options.automatic_resolution = false;
    run.options.nlp.knots_per_interval = 1;
    run.result = optimize_motion(dive.file.motion, dive.file.model, run.options);
    log(dive.label + ": " + run.result.solve.status);
    report.dives.push_back(std::move(run));
  }

  // Mass study on the hardest skill (§6.1, Fig. 8).
  const auto m7 = std::find_if(skills.begin(), skills.end(),
                               [](const LabelledMotion& m) { return m.label == "M7"; });
  report.mass_options.optimize = options.optimize;
  report.mass_options.optimize.automatic_resolution = false;
  if (m7 != skills.end()) {
    report.mass = run_mass_study(m7->file, report.mass_options);
    log("mass study done");
  }

  // Convergence study (§3.4's claim).
  ConvergenceStudyOptions& convergence = report.convergence_options;
  convergence.optimize = options.optimize;
  convergence.optimize.automatic_resolution = false;  // the paper's protocol: its resolution
  std::vector<LabelledMotion> study_motions = skills;
  // The paper's mass-parameter errors hit every segment alike; a single segment's error (the
  // right thigh, as in the mass study) also breaks the body's left-right symmetry.
  convergence.mass_segments = {"all", "thigh_r"};
  if (options.quick) {
    convergence.mass_segments = {"all"};
    study_motions = {skills.front()};
    if (skills.size() > 1) study_motions.push_back(skills.back());
    convergence.epsilons = {10, 500};
    convergence.mass_errors = {-0.2, 0.0, 0.2};
    convergence.timing_errors = {0.0, 0.1};
  }
  report.convergence = run_convergence_study(
      study_motions, convergence, [&](int done, int total, const StudyOutcome& o) {
        log("convergence " + std::to_string(done) + "/" + std::to_string(total) + ": " +
            o.study_case.motion + " " + formulation_label(o.study_case) + " " + o.status);
      });
  return report;
}

}  // namespace saltus
