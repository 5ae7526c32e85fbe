#include "saltus/formats/paper_report_files.h"

#include <algorithm>
#include <filesystem>
#include <sstream>

#include "saltus/base/input_error.h"
#include "saltus/base/text_format.h"
#include "saltus/formats/convergence_files.h"
#include "saltus/formats/mass_files.h"
#include "saltus/formats/motion_file.h"
#include "saltus/formats/output_folder.h"
#include "saltus/formats/result_json.h"
#include "saltus/studies/paper_table1.h"

namespace saltus {

namespace {

std::string table1_markdown(const std::vector<PaperSkillRun>& rows) {
  std::ostringstream out;
  out << "| skill | keyframes | variables | constraints | J before | J after | avg root force "
         "before (N) | avg root force after (N) | iterations | time (s) | status | after, K = 3 "
         "(N) |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const PaperSkillRun& r : rows) {
    const OptimizationResult& o = r.paper_resolution;
    out << "| " << r.motion.label << " | " << r.motion.file.motion.keyframes.size() << " | "
        << o.variables << " | " << o.constraints << " | "
        << format_number("%.3g", o.before.metrics.objective) << " | "
        << format_number("%.3g", o.after.metrics.objective) << " | "
        << format_number("%.3g", o.before.metrics.avg_root_force) << " | "
        << format_number("%.3g", o.after.metrics.avg_root_force) << " | " << o.solve.iterations
        << " | " << format_number("%.2f", o.solve.seconds) << " | " << o.solve.status << " | "
        << (r.refined ? format_number("%.3g", r.refined->after.metrics.avg_root_force) + " (" +
                            std::to_string(r.refined->solve.iterations) + " it., " +
                            format_number("%.1f", r.refined->solve.seconds) + " s, " +
                            r.refined->solve.status + ")"
                      : std::string("–"))
        << " |\n";
  }
  out << "\nThe paper's Table 1 (SQP, at most 80 iterations, 78 minutes per motion on average):\n\n"
         "| skill | keyframes | variables | constraints | J before | J after | avg root force "
         "before (N) | avg root force after (N) |\n|---|---|---|---|---|---|---|---|\n";
  for (const PaperTableRow& p : kPaperTable1)
    out << "| " << p.label << " | " << p.keyframes << " | " << p.variables << " | " << p.constraints
        << " | " << format_number("%.3g", p.objective_before) << " | "
        << format_number("%.3g", p.objective_after) << " | "
        << format_number("%.3g", p.force_before) << " | " << format_number("%.3g", p.force_after)
        << " |\n";
  out << "\nAverage root force after optimisation, ours (K = 1, the paper's resolution) against "
         "the paper's:\n\n| skill | ours (N) | paper (N) | ours below paper |\n|---|---|---|---|\n";
  for (const PaperSkillRun& r : rows) {
    const PaperTableRow* p = paper_table1(r.motion.label);
    if (!p) continue;
    const double ours = r.paper_resolution.after.metrics.avg_root_force;
    out << "| " << r.motion.label << " | " << format_number("%.3g", ours) << " | "
        << format_number("%.3g", p->force_after) << " | " << (ours < p->force_after ? "yes" : "NO")
        << " |\n";
  }
  return out.str();
}

/// Figs. 4 and 5: M1's and M7's root force before and after, where those skills were run.
std::string root_force_figures(const std::vector<PaperSkillRun>& rows) {
  std::ostringstream out;
  for (const PaperSkillRun& run : rows) {
    const std::string& label = run.motion.label;
    if (label != "M1" && label != "M7") continue;
    out << "![" << label << " root force before and after](figures/" << label
        << "_root_force.png)\n\nThe curves are in `" << label << "/trajectory_before.csv` and `"
        << label << "/trajectory_after.csv` (columns root_fx … root_mz).\n\n";
  }
  return out.str();
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

nlohmann::json write_paper_report(const std::string& out_dir, const PaperReportOptions& options) {
  const PaperMotions motions = load_paper_motions(options.motions_dir);
  OutputFolder folder(out_dir);
  const PaperReport report = run_paper_report(motions.skills, motions.dives, options);

  for (const PaperSkillRun& run : report.skills)
    write_optimization_outputs(folder.file(run.motion.label), run.motion.file, run.paper_resolution,
                               run.options);

  // The 5 m dive (§6.2): keyframe times before and after (Fig. 9).
  std::ostringstream dive_md;
  for (const PaperDiveRun& run : report.dives) {
    const std::string& label = run.motion.label;
    const OptimizationResult& r = run.result;
    write_optimization_outputs(folder.file(label), run.motion.file, r, run.options);
    dive_md << "**" << run.motion.file.motion.name << "** (`" << label << "/`): " << r.solve.status
            << " after " << r.solve.iterations << " iterations, "
            << format_number("%.2f", r.solve.seconds) << " s; average root force "
            << format_number("%.3g", r.before.metrics.avg_root_force) << " N → "
            << format_number("%.3g", r.after.metrics.avg_root_force) << " N.\n\n"
            << "| keyframe | time given (s) | time optimised (s) |\n|---|---|---|\n";
    for (std::size_t i = 0; i < r.before.keyframe_times.size(); ++i)
      dive_md << "| " << i + 1 << " | " << format_number("%.3f", r.before.keyframe_times[i])
              << " | " << format_number("%.3f", r.after.keyframe_times[i]) << " |\n";
    dive_md << "\n![Keyframe times before and after (Fig. 9)](figures/" << label
            << "_keyframe_times.png)\n\n";
  }

  std::string mass_md = "No M7 in " + options.motions_dir + ".\n";
  if (report.mass) {
    const auto m7 = std::find_if(motions.skills.begin(), motions.skills.end(),
                                 [](const LabelledMotion& m) { return m.label == "M7"; });
    write_mass_outputs(folder.file("mass"), m7->file, *report.mass, report.mass_options);
    mass_md = mass_study_markdown(*report.mass) +
              "\n![Joint loads, Table 2 against thigh +50 % (Fig. 8)](figures/mass_loads.png)\n";
  }
  write_convergence_outputs(folder.file("convergence"), report.convergence,
                            report.convergence_options);

  std::ostringstream md;
  md << "# Saltus: the paper's experiments, reproduced\n\n"
     << "Wei, Xia & Wang, *Physics-based simulation of human motion in flight*, J. Software "
        "2008 — §3.4 (Table 1, Figs. 4-5), §6.1 (Fig. 8), §6.2 (Figs. 9-10).\n\n"
     << "**Our keyframes are our own.** The paper's motion capture is not public, so M1-M7 here "
        "are keyframed by us (examples/README.md describes each) with the paper's keyframe "
        "counts, take-off state (CoM (0, 1, 0) m, velocity (0.15, 10, 0.15) m/s), flight time "
        "(2.04 s) and tolerances (ε1 = 0.25 m, ε2 = 0.05). The comparison is of method and "
        "magnitude, not of identical inputs.\n\n"
     << "Settings: relaxed model, " << options.optimize.nlp.samples
     << " samples, timing optimised, Ipopt with exact first derivatives and a Gauss-Newton "
        "Hessian; the root wrench and its derivatives on "
     << (options.optimize.nlp.threads > 0
             ? std::to_string(options.optimize.nlp.threads) + " threads"
             : std::string("one thread per hardware thread (at most 4)"))
     << ", Ipopt's linear solver (MUMPS) on one."
     << (options.quick ? " **Quick run** (reduced convergence study, no K = 3 runs)." : "")
     << "\n\n## Table 1\n\n"
     << table1_markdown(report.skills) << "\n## Root force before and after (Figs. 4 and 5)\n\n"
     << root_force_figures(report.skills)
     << "## Mass parameters (§6.1, Fig. 8): M7 with Table 2 against thigh mass and inertia "
        "+50 %\n\n"
     << mass_md << "\n## Designing a 5 m dive by optimising keyframe times (§6.2, Fig. 9)\n\n"
     << (report.dives.empty() ? std::string("No dive motion in the folder.\n\n") : dive_md.str())
     << "## Convergence study (§3.4)\n\n"
     << convergence_markdown(report.convergence)
     << "\nEvery case is in `convergence/convergence.csv`.\n";
  write_text(folder.file("report.md"), md.str());

  nlohmann::json result;
  result["format"] = "saltus-report/1";
  result["status"] = "completed";
  result["quick"] = options.quick;
  result["table1"] = nlohmann::json::array();
  for (const PaperSkillRun& r : report.skills) {
    const OptimizationResult& o = r.paper_resolution;
    nlohmann::json row = {{"skill", r.motion.label},
                          {"keyframes", r.motion.file.motion.keyframes.size()},
                          {"variables", o.variables},
                          {"constraints", o.constraints},
                          {"status", o.solve.status},
                          {"iterations", o.solve.iterations},
                          {"seconds", o.solve.seconds},
                          {"objective_before", o.before.metrics.objective},
                          {"objective_after", o.after.metrics.objective},
                          {"avg_force_before_N", o.before.metrics.avg_root_force},
                          {"avg_force_after_N", o.after.metrics.avg_root_force}};
    row["avg_force_after_K3_N"] = r.refined
                                      ? nlohmann::json(r.refined->after.metrics.avg_root_force)
                                      : nlohmann::json(nullptr);
    if (const PaperTableRow* p = paper_table1(r.motion.label))
      row["paper_avg_force_after_N"] = p->force_after;
    result["table1"].push_back(row);
  }
  int solved = 0;
  for (const StudyOutcome& o : report.convergence)
    solved += o.solved && o.study_case.formulation == Formulation::kRelaxed ? 1 : 0;
  int relaxed = 0;
  for (const StudyOutcome& o : report.convergence)
    relaxed += o.study_case.formulation == Formulation::kRelaxed ? 1 : 0;
  result["convergence_relaxed_solved"] = solved;
  result["convergence_relaxed_cases"] = relaxed;
  write_text(folder.file("result.json"), result.dump(2) + "\n");
  folder.commit();
  return result;
}

}  // namespace saltus
