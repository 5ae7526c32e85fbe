#include "saltus/formats/paper_report_files.h"

#include <algorithm>
#include <filesystem>
#include <memory>
#include <sstream>

#include "saltus/base/input_error.h"
#include "saltus/base/json_reader.h"
#include "saltus/base/text_format.h"
#include "saltus/formats/convergence_files.h"
#include "saltus/formats/mass_files.h"
#include "saltus/formats/motion_file.h"
#include "saltus/formats/output_folder.h"
#include "saltus/formats/result_json.h"
#include "saltus/studies/paper_table1.h"

namespace saltus {

namespace {

std::string number_or_dash(const RunSummary& r, const char* pattern, double value) {
  return r.completed() ? format_number(pattern, value) : std::string("–");
}

std::string table1_markdown(const std::vector<PaperSkillRow>& rows) {
  std::ostringstream out;
  out << "| skill | keyframes | variables | constraints | J before | J after | avg root force "
         "before (N) | avg root force after (N) | iterations | time (s) | status | after, K = 3 "
         "(N) |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const PaperSkillRow& row : rows) {
    const RunSummary& o = row.paper_resolution;
    out << "| " << row.label << " | " << o.keyframes << " | "
        << (o.completed() ? std::to_string(o.variables) : "–") << " | "
        << (o.completed() ? std::to_string(o.constraints) : "–") << " | "
        << number_or_dash(o, "%.3g", o.objective_before) << " | "
        << number_or_dash(o, "%.3g", o.objective_after) << " | "
        << number_or_dash(o, "%.3g", o.avg_force_before) << " | "
        << number_or_dash(o, "%.3g", o.avg_force_after) << " | "
        << (o.completed() ? std::to_string(o.iterations) : "–") << " | "
        << number_or_dash(o, "%.2f", o.seconds) << " | " << o.status << " | ";
    if (!row.refined)
      out << "–";
    else if (!row.refined->completed())
      out << row.refined->status;
    else
      out << format_number("%.3g", row.refined->avg_force_after) << " (" << row.refined->iterations
          << " it., " << row.refined->status << ")";
    out << " |\n";
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
  for (const PaperSkillRow& row : rows) {
    const PaperTableRow* p = paper_table1(row.label);
    if (!p) continue;
    const RunSummary& o = row.paper_resolution;
    const double ours = o.avg_force_after;
    out << "| " << row.label << " | " << number_or_dash(o, "%.3g", ours) << " | "
        << format_number("%.3g", p->force_after) << " | "
        << (!o.completed()          ? "–"
            : ours < p->force_after ? "yes"
                                    : "NO")
        << " |\n";
  }
  return out.str();
}

/// Figs. 4 and 5: M1's and M7's root force before and after, where those skills were run.
std::string root_force_figures(const std::vector<PaperSkillRow>& rows) {
  std::ostringstream out;
  for (const PaperSkillRow& row : rows) {
    const std::string& label = row.label;
    if (label != "M1" && label != "M7") continue;
    out << "![" << label << " root force before and after](figures/" << label
        << "_root_force.png)\n\nThe curves are in `" << label << "/trajectory_before.csv` and `"
        << label << "/trajectory_after.csv` (columns root_fx … root_mz).\n\n";
  }
  return out.str();
}

std::string dive_markdown(const std::vector<PaperDiveRow>& dives) {
  std::ostringstream out;
  for (const PaperDiveRow& dive : dives) {
    const RunSummary& r = dive.run;
    out << "**" << r.motion_name << "** (`" << dive.label << "/`): " << r.status;
    if (!r.completed()) {
      out << ".\n\n";
      continue;
    }
    out << " after " << r.iterations << " iterations; average root force "
        << format_number("%.3g", r.avg_force_before) << " N → "
        << format_number("%.3g", r.avg_force_after) << " N.\n\n"
        << "| keyframe | time given (s) | time optimised (s) |\n|---|---|---|\n";
    for (std::size_t i = 0; i < r.keyframe_times_before.size(); ++i)
      out << "| " << i + 1 << " | " << format_number("%.3f", r.keyframe_times_before[i]) << " | "
          << format_number("%.3f", r.keyframe_times_after[i]) << " |\n";
    out << "\n![Keyframe times before and after (Fig. 9)](figures/" << dive.label
        << "_keyframe_times.png)\n\n";
  }
  return out.str();
}

/// The settings the report states, from its definition.
struct ReportSettings {
  bool quick = false;
  int samples = 0;
  int threads = 0;
};

ReportSettings read_report_settings(const nlohmann::json& definition) {
  const JsonNode root(definition, "study.json", "/definition");
  ReportSettings s;
  if (!root.at("quick").value().is_boolean()) root.at("quick").fail("expected true or false");
  s.quick = root.at("quick").value().get<bool>();
  s.samples = root.at("optimize").at("samples").as_int();
  // A number, or "auto" (one per hardware thread): 0 here.
  const JsonNode threads = root.at("optimize").at("threads");
  s.threads = threads.value().is_string() ? 0 : threads.as_int();
  return s;
}

}  // namespace

const FolderKind& paper_report_folder_kind() {
  static const FolderKind kind{
      "paper", {"result.json", "report.md", "study.json"}, {"figures"}, {"cases"}, true};
  return kind;
}

nlohmann::json write_paper_report_files(const OutputFolder& folder,
                                        const nlohmann::json& definition, const PaperReport& report,
                                        int failed_cases) {
  const ReportSettings settings = read_report_settings(definition);
  write_convergence_files(folder.file("convergence"), report.convergence,
                          definition.at("convergence"));
  write_folder_record(folder.file("convergence"), convergence_folder_kind());

  std::string mass_md = report.mass_markdown;
  if (report.has_mass)
    mass_md += "\n![Joint loads, Table 2 against thigh +50 % (Fig. 8)](figures/mass_loads.png)\n";

  std::ostringstream md;
  md << "# Saltus: the paper's experiments, reproduced\n\n"
     << "Wei, Xia & Wang, *Physics-based simulation of human motion in flight*, J. Software "
        "2008 — §3.4 (Table 1, Figs. 4-5), §6.1 (Fig. 8), §6.2 (Figs. 9-10).\n\n"
     << "**Our keyframes are our own.** The paper's motion capture is not public, so M1-M7 here "
        "are keyframed by us (examples/README.md describes each) with the paper's keyframe "
        "counts, take-off state (CoM (0, 1, 0) m, velocity (0.15, 10, 0.15) m/s), flight time "
        "(2.04 s) and tolerances (ε1 = 0.25 m, ε2 = 0.05). The comparison is of method and "
        "magnitude, not of identical inputs.\n\n"
     << "Settings: relaxed model, " << settings.samples
     << " samples, timing optimised, Ipopt with exact first derivatives and a Gauss-Newton "
        "Hessian; the root wrench and its derivatives on "
     << (settings.threads > 0 ? std::to_string(settings.threads) + " threads"
                              : std::string("one thread per hardware thread (at most 4)"))
     << ", Ipopt's linear solver (MUMPS) on one; every run in a process of its own."
     << (settings.quick ? " **Quick run** (reduced convergence study, no K = 3 runs)." : "")
     << "\n\n## Table 1\n\n"
     << table1_markdown(report.skills) << "\n## Root force before and after (Figs. 4 and 5)\n\n"
     << root_force_figures(report.skills)
     << "## Mass parameters (§6.1, Fig. 8): M7 with Table 2 against thigh mass and inertia "
        "+50 %\n\n"
     << mass_md << "\n## Designing a 5 m dive by optimising keyframe times (§6.2, Fig. 9)\n\n"
     << (report.dives.empty() ? std::string("No dive motion in the folder.\n\n")
                              : dive_markdown(report.dives))
     << "## Convergence study (§3.4)\n\n"
     << convergence_markdown(report.convergence)
     << "\nEvery case is in `convergence/convergence.csv`.\n";
  write_text(folder.file("report.md"), md.str());

  nlohmann::json result;
  result["format"] = "saltus-report/1";
  result["status"] = "completed";
  result["quick"] = settings.quick;
  result["table1"] = nlohmann::json::array();
  auto number = [](const RunSummary& r, double value) {
    return r.completed() ? nlohmann::json(value) : nlohmann::json(nullptr);
  };
  for (const PaperSkillRow& row : report.skills) {
    const RunSummary& o = row.paper_resolution;
    nlohmann::json j = {{"skill", row.label},
                        {"keyframes", o.keyframes},
                        {"variables", o.variables},
                        {"constraints", o.constraints},
                        {"status", o.status},
                        {"iterations", o.iterations},
                        {"seconds", o.seconds},
                        {"objective_before", number(o, o.objective_before)},
                        {"objective_after", number(o, o.objective_after)},
                        {"avg_force_before_N", number(o, o.avg_force_before)},
                        {"avg_force_after_N", number(o, o.avg_force_after)}};
    j["avg_force_after_K3_N"] =
        row.refined ? number(*row.refined, row.refined->avg_force_after) : nlohmann::json(nullptr);
    if (const PaperTableRow* p = paper_table1(row.label))
      j["paper_avg_force_after_N"] = p->force_after;
    result["table1"].push_back(j);
  }
  int solved = 0, relaxed = 0;
  for (const StudyOutcome& o : report.convergence) {
    const bool is_relaxed = o.study_case.formulation == Formulation::kRelaxed;
    relaxed += is_relaxed ? 1 : 0;
    solved += is_relaxed && o.solved ? 1 : 0;
  }
  result["convergence_relaxed_solved"] = solved;
  result["convergence_relaxed_cases"] = relaxed;
  result["failed_cases"] = failed_cases;
  write_text(folder.file("result.json"), result.dump(2) + "\n");
  return result;
}

}  // namespace saltus
