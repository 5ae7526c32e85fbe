#include "saltus/studies/paper_report.h"

namespace saltus {

PaperPlan paper_report_plan(const std::vector<LabelledMotion>& skills,
                            const std::vector<LabelledMotion>& dives,
                            const PaperReportOptions& options) {
  PaperPlan plan;
  for (const LabelledMotion& skill : skills) {
    plan.cases.push_back({PaperCaseKind::kSkill, skill.label, {}});
    if (!options.quick) plan.cases.push_back({PaperCaseKind::kRefinedSkill, skill.label, {}});
  }
  // The 5 m dive (§6.2): keyframe times before and after (Fig. 9).
  for (const LabelledMotion& dive : dives)
    plan.cases.push_back({PaperCaseKind::kDive, dive.label, {}});
  // Mass study on the hardest skill (§6.1, Fig. 8), optimised as `optimize` does: at the paper's
  // resolution the joints pay for the root force with loads many times the input's.
  plan.mass.optimize = options.optimize;
  for (const LabelledMotion& skill : skills)
    if (skill.label == "M7") plan.cases.push_back({PaperCaseKind::kMass, skill.label, {}});

  // Convergence study (§3.4's claim).
  ConvergenceStudyOptions& convergence = plan.convergence;
  convergence.optimize = options.optimize;
  use_paper_protocol(convergence.optimize);
  convergence.strict_checkpoints = options.strict_checkpoints;
  plan.convergence_motions = skills;
  // The paper's mass-parameter errors hit every segment alike; a single segment's error (the
  // right thigh, as in the mass study) also breaks the body's left-right symmetry.
  convergence.mass_segments = {"all", "thigh_r"};
  if (options.quick) {
    convergence.mass_segments = {"all"};
    plan.convergence_motions = {skills.front()};
    if (skills.size() > 1) plan.convergence_motions.push_back(skills.back());
    convergence.epsilons = {10, 500};
    convergence.mass_errors = {-0.2, 0.0, 0.2};
    convergence.timing_errors = {0.0, 0.1};
  }
  for (const StudyCase& c : convergence_study_cases(plan.convergence_motions, convergence))
    plan.cases.push_back({PaperCaseKind::kConvergence, c.motion, c});
  return plan;
}

OptimizeOptions paper_run_options(const PaperCase& paper_case, const PaperReportOptions& options) {
  OptimizeOptions o = options.optimize;
  use_paper_protocol(o);  // knots at the keyframes (or K = 3), no keyframe prior
  o.nlp.knots_per_interval = paper_case.kind == PaperCaseKind::kRefinedSkill ? 3 : 1;
  return o;
}

std::string paper_case_label(const PaperCase& paper_case) {
  switch (paper_case.kind) {
    case PaperCaseKind::kSkill:
      return paper_case.motion;
    case PaperCaseKind::kRefinedSkill:
      return paper_case.motion + ", K = 3";
    case PaperCaseKind::kDive:
      return paper_case.motion;
    case PaperCaseKind::kMass:
      return "mass study on " + paper_case.motion;
    case PaperCaseKind::kConvergence:
      return study_case_label(paper_case.convergence);
  }
  return paper_case.motion;
}

}  // namespace saltus
