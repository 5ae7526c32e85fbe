#include "saltus/use_cases/paper_report_run.h"

#include <algorithm>
#include <filesystem>
#include <memory>

#include "saltus/base/input_error.h"
#include "saltus/formats/convergence_files.h"
#include "saltus/formats/mass_files.h"
#include "saltus/formats/motion_file.h"
#include "saltus/formats/paper_report_files.h"
#include "saltus/formats/study_folder.h"
#include "saltus/optim/option_table.h"
#include "saltus/studies/paper_table1.h"
#include "saltus/use_cases/result_folders.h"

namespace saltus {

namespace {

/// The report's runs back from their records (in case order).
PaperReport assemble_report(const std::vector<CaseRecord>& records) {
  PaperReport report;
  report.mass_markdown = "No M7 among the motions.\n";
  for (const CaseRecord& r : records) {
    if (r.role == "skill") {
      report.skills.push_back({r.motion, r.run, std::nullopt});
    } else if (r.role == "refined_skill") {
      const auto row = std::find_if(report.skills.begin(), report.skills.end(),
                                    [&](const PaperSkillRow& s) { return s.label == r.motion; });
      if (row == report.skills.end())
        throw InputError(case_record_name(r.index), "/motion",
                         "a K = 3 run of " + r.motion + " without its K = 1 run");
      row->refined = r.run;
    } else if (r.role == "dive") {
      report.dives.push_back({r.motion, r.run});
    } else if (r.role == "mass") {
      report.has_mass = r.finished();
      report.mass_markdown =
          r.finished() ? r.mass_markdown : "The mass study did not finish (" + r.failure + ").\n";
    } else if (r.role == "convergence") {
      report.convergence.push_back(r.convergence);
    } else {
      throw InputError(case_record_name(r.index), "/role",
                       "\"" + r.role + "\" is not a part of the report");
    }
  }
  return report;
}

const char* role_of(PaperCaseKind kind) {
  switch (kind) {
    case PaperCaseKind::kSkill:
      return "skill";
    case PaperCaseKind::kRefinedSkill:
      return "refined_skill";
    case PaperCaseKind::kDive:
      return "dive";
    case PaperCaseKind::kMass:
      return "mass";
    case PaperCaseKind::kConvergence:
      return "convergence";
  }
  return "";
}

nlohmann::json motion_list(const std::vector<LabelledMotion>& motions) {
  nlohmann::json list = nlohmann::json::array();
  for (const LabelledMotion& m : motions)
    list.push_back({{"label", m.label}, {"digest", motion_digest(m.file)}});
  return list;
}

}  // namespace

PaperMotions load_paper_motions(const std::string& motions_dir) {
  namespace fs = std::filesystem;
  if (!fs::is_directory(motions_dir))
    throw InputError(motions_dir, "", "not a folder of motion files");
  std::vector<std::pair<std::string, fs::path>> skills, dives;
  for (const auto& entry : fs::directory_iterator(motions_dir)) {
    const std::string name = entry.path().filename().string();
    if (name.size() <= 12 || name.substr(name.size() - 12) != ".motion.json") continue;
    const std::string label = motion_label(entry.path().string());
    if (paper_table1(label))
      skills.emplace_back(label, entry.path());
    else if (name.rfind("dive", 0) == 0)
      dives.emplace_back(label, entry.path());
  }
  std::sort(skills.begin(), skills.end());
  std::sort(dives.begin(), dives.end());
  if (skills.empty())
    throw InputError(motions_dir, "", "no M1-…M7-….motion.json files in this folder");
  PaperMotions motions;
  for (const auto& [label, path] : skills)
    motions.skills.push_back({label, load_motion_file(path.string())});
  for (const auto& [label, path] : dives)
    motions.dives.push_back({label, load_motion_file(path.string())});
  return motions;
}

StudyJob paper_report_job(const PaperReportOptions& options) {
  const auto motions =
      std::make_shared<const PaperMotions>(load_paper_motions(options.motions_dir));
  const auto plan = std::make_shared<const PaperPlan>(
      paper_report_plan(motions->skills, motions->dives, options));
  StudyJob job;
  job.study = kPaperReportStudy;
  job.definition = {
      {"skills", motion_list(motions->skills)},
      {"dives", motion_list(motions->dives)},
      {"quick", options.quick},
      {"optimize", result_deciding_settings(options.optimize)},
      {"mass",
       {{"scaled_segments", plan->mass.scaled_segments},
        {"factor", plan->mass.factor},
        {"load_segments", plan->mass.load_segments},
        {"paper_protocol", plan->mass.paper_protocol}}},
      {"convergence", convergence_definition(plan->convergence_motions, plan->convergence)}};
  for (const PaperCase& c : plan->cases)
    job.case_names.push_back(paper_case_label(c));
  auto find = [motions](const std::string& label) -> const LabelledMotion& {
    for (const auto* list : {&motions->skills, &motions->dives})
      for (const LabelledMotion& m : *list)
        if (m.label == label) return m;
    throw std::logic_error("no motion " + label);
  };
  auto base_record = [plan](int index) {
    const PaperCase& c = plan->cases[index];
    CaseRecord r;
    r.index = index;
    r.name = paper_case_label(c);
    r.role = role_of(c.kind);
    r.motion = c.motion;
    r.kind = c.kind == PaperCaseKind::kMass          ? CaseKind::kMassStudy
             : c.kind == PaperCaseKind::kConvergence ? CaseKind::kConvergence
                                                     : CaseKind::kOptimization;
    return r;
  };
  job.run_case = [plan, options, find, base_record](int index, const std::string& dir) {
    const PaperCase& c = plan->cases[index];
    CaseRecord r = base_record(index);
    const LabelledMotion& motion = find(c.motion);
    const std::filesystem::path folder(dir);
    switch (c.kind) {
      case PaperCaseKind::kSkill:
      case PaperCaseKind::kRefinedSkill:
      case PaperCaseKind::kDive: {
        const OptimizeOptions run_options = paper_run_options(c, options);
        const OptimizationResult result =
            optimize_motion(motion.file.motion, motion.file.model, run_options);
        if (c.kind != PaperCaseKind::kRefinedSkill) {
          r.folder = c.motion;
          write_optimization_outputs((folder / r.folder).string(), motion.file, result,
                                     run_options);
        }
        r.run = summarize_run(motion.file.motion, result);
        break;
      }
      case PaperCaseKind::kMass: {
        const MassStudyResult study = run_mass_study(motion.file, plan->mass);
        r.folder = "mass";
        write_mass_outputs((folder / r.folder).string(), motion.file, study, plan->mass);
        r.mass_markdown = mass_study_markdown(study);
        break;
      }
      case PaperCaseKind::kConvergence:
        r.convergence = run_study_case(motion, c.convergence, plan->convergence);
        break;
    }
    return r;
  };
  job.unfinished_case = [plan, find, base_record](int index, const WorkerExit& exit) {
    const PaperCase& c = plan->cases[index];
    CaseRecord r = base_record(index);
    r.failure = exit.describe();
    const std::string status = exit.kind == WorkerExit::Kind::kTimedOut ? "timed_out" : "crashed";
    if (r.kind == CaseKind::kConvergence) {
      r.convergence = unfinished_outcome(c.convergence, status, exit.seconds);
    } else if (r.kind == CaseKind::kOptimization) {
      const Motion& m = find(c.motion).file.motion;
      r.run.motion_name = m.name;
      r.run.keyframes = static_cast<int>(m.keyframes.size());
      r.run.status = status;
      r.run.seconds = exit.seconds;
    }
    return r;
  };
  return job;
}

nlohmann::json write_paper_report_outputs(const OutputFolder& folder,
                                          const nlohmann::json& definition,
                                          const std::vector<CaseRecord>& records) {
  int failed = 0;
  for (const CaseRecord& r : records)
    failed += r.finished() ? 0 : 1;
  return write_paper_report_files(folder, definition, assemble_report(records), failed);
}

}  // namespace saltus
