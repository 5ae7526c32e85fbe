#include "saltus/io/study_outputs.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>

#include "saltus/io/input_error.h"
#include "saltus/io/output_folder.h"
#include "saltus/io/result_files.h"

namespace saltus {

const PaperTableRow kPaperTable1[7] = {
    {"M1", 5, 264, 89, 3.88e3, 5.27e1, 25.4, 2.96},
    {"M2", 7, 350, 125, 8.66e4, 1.82e3, 120, 17.4},
    {"M3", 8, 393, 143, 6.40e4, 4.57e3, 103, 27.5},
    {"M4", 9, 436, 161, 1.44e5, 1.27e4, 154, 46.0},
    {"M5", 11, 522, 197, 4.48e5, 1.21e4, 273, 44.9},
    {"M6", 11, 522, 197, 1.61e5, 5.05e3, 163, 29.0},
    {"M7", 13, 595, 233, 4.15e5, 4.08e4, 262, 82.4},
};

namespace {

nlohmann::json outcome_json(const StudyOutcome& o) {
  const StudyCase& c = o.study_case;
  return {{"motion", c.motion},
          {"formulation", c.formulation == Formulation::kRelaxed ? "relaxed" : "strict"},
          {"epsilon", c.epsilon},
          {"mass_segment", c.mass_segment},
          {"mass_error", c.mass_error},
          {"timing_error_s", c.timing_error_s},
          {"status", o.status},
          {"solved", o.solved},
          {"iterations", o.iterations},
          {"seconds", o.seconds},
          {"avg_force_before_N", o.avg_force_before},
          {"avg_force_after_N", o.avg_force_after}};
}

struct Table1Row {
  std::string label;
  std::string name;
  int keyframes = 0;
  OptimizationResult paper_resolution;  ///< K = 1
  bool refined_run = false;
  double refined_force_after = 0.0;  ///< K = 3
  int refined_iterations = 0;
  double refined_seconds = 0.0;
  std::string refined_status;
};

std::string table1_markdown(const std::vector<Table1Row>& rows) {
  std::ostringstream out;
  out << "| skill | keyframes | variables | constraints | J before | J after | avg root force "
         "before (N) | avg root force after (N) | iterations | time (s) | status | after, K = 3 "
         "(N) |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const Table1Row& r : rows) {
    const OptimizationResult& o = r.paper_resolution;
    out << "| " << r.label << " | " << r.keyframes << " | " << o.variables << " | " << o.constraints
        << " | " << format_number("%.3g", o.before.metrics.objective) << " | "
        << format_number("%.3g", o.after.metrics.objective) << " | "
        << format_number("%.3g", o.before.metrics.avg_root_force) << " | "
        << format_number("%.3g", o.after.metrics.avg_root_force) << " | " << o.solve.iterations
        << " | " << format_number("%.2f", o.solve.seconds) << " | " << o.solve.status << " | "
        << (r.refined_run
                ? format_number("%.3g", r.refined_force_after) + " (" +
                      std::to_string(r.refined_iterations) + " it., " +
                      format_number("%.1f", r.refined_seconds) + " s, " + r.refined_status + ")"
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
  for (const Table1Row& r : rows) {
    const PaperTableRow* p = paper_table1(r.label);
    if (!p) continue;
    const double ours = r.paper_resolution.after.metrics.avg_root_force;
    out << "| " << r.label << " | " << format_number("%.3g", ours) << " | "
        << format_number("%.3g", p->force_after) << " | " << (ours < p->force_after ? "yes" : "NO")
        << " |\n";
  }
  return out.str();
}

/// Figs. 4 and 5: M1's and M7's root force before and after, where those skills were run.
std::string root_force_figures(const std::vector<Table1Row>& rows) {
  std::ostringstream out;
  for (const Table1Row& r : rows) {
    if (r.label != "M1" && r.label != "M7") continue;
    out << "![" << r.label << " root force before and after](figures/" << r.label
        << "_root_force.png)\n\nThe curves are in `" << r.label << "/trajectory_before.csv` and `"
        << r.label << "/trajectory_after.csv` (columns root_fx … root_mz).\n\n";
  }
  return out.str();
}

}  // namespace

const PaperTableRow* paper_table1(const std::string& skill) {
  for (const PaperTableRow& row : kPaperTable1)
    if (skill == row.label) return &row;
  return nullptr;
}

nlohmann::json write_convergence_outputs(const std::string& out_dir,
                                         const std::vector<StudyOutcome>& outcomes,
                                         const ConvergenceStudyOptions& options) {
  OutputFolder folder(out_dir);
  nlohmann::json result;
  result["format"] = "saltus-study/1";
  result["study"] = "convergence";
  result["status"] = "completed";
  result["seed"] = options.seed;
  result["samples"] = options.optimize.nlp.samples;
  result["knots_per_interval"] = options.optimize.nlp.knots_per_interval;
  result["max_iterations"] = options.optimize.solver.max_iterations;
  result["cases"] = nlohmann::json::array();
  for (const StudyOutcome& o : outcomes)
    result["cases"].push_back(outcome_json(o));
  write_text(folder.file("convergence.csv"), convergence_csv(outcomes));
  write_text(folder.file("convergence.md"),
             "# Convergence study\n\n" + convergence_markdown(outcomes));
  write_text(folder.file("result.json"), result.dump(2) + "\n");
  folder.commit();
  return result;
}

nlohmann::json write_mass_outputs(const std::string& out_dir, const MotionFile& file,
                                  const MassStudyResult& study, const MassStudyOptions& options) {
  OutputFolder folder(out_dir);
  nlohmann::json result;
  result["format"] = "saltus-study/1";
  result["study"] = "mass";
  result["status"] = "completed";
  result["motion"] = file.motion.name;
  result["motion_file"] = file.path;
  result["factor"] = options.factor;
  result["scaled_segments"] = options.scaled_segments;
  result["load_segments"] = study.load_segments;
  result["runs"] = nlohmann::json::array();
  for (const MassStudyRun& run : study.runs)
    result["runs"].push_back({{"label", run.label},
                              {"model", run.model.name},
                              {"status", run.result.solve.status},
                              {"iterations", run.result.solve.iterations},
                              {"avg_force_before_N", run.result.before.metrics.avg_root_force},
                              {"avg_force_after_N", run.result.after.metrics.avg_root_force}});
  write_text(folder.file("mass.csv"), mass_study_csv(study));
  write_text(folder.file("mass.md"),
             "# Mass study: " + file.motion.name + "\n\n" + mass_study_markdown(study));
  write_text(folder.file("model.json"), body_model_to_json(study.runs[0].model).dump(2) + "\n");
  write_text(folder.file("model_scaled.json"),
             body_model_to_json(study.runs[1].model).dump(2) + "\n");
  write_text(folder.file("result.json"), result.dump(2) + "\n");
  folder.commit();
  return result;
}

nlohmann::json write_paper_report(const std::string& out_dir, const PaperReportOptions& options) {
  namespace fs = std::filesystem;
  auto log = [&](const std::string& line) {
    if (options.log) options.log(line);
  };
  if (!fs::is_directory(options.motions_dir))
    throw InputError(options.motions_dir, "", "not a folder of motion files");
  std::vector<std::pair<std::string, fs::path>> skills, dives;
  for (const auto& entry : fs::directory_iterator(options.motions_dir)) {
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
    throw InputError(options.motions_dir, "", "no M1-…M7-….motion.json files in this folder");

  OutputFolder folder(out_dir);
  std::vector<Table1Row> rows;
  std::vector<LabelledMotion> loaded;
  for (const auto& [label, path] : skills) {
    const MotionFile file = load_motion_file(path.string());
    loaded.push_back({label, file});
    Table1Row row;
    row.label = label;
    row.name = file.motion.name;
    row.keyframes = static_cast<int>(file.motion.keyframes.size());
    OptimizeOptions k1 = options.optimize;
    k1.nlp.knots_per_interval = 1;
    row.paper_resolution = optimize_motion(file.motion, file.model, k1);
    write_optimization_outputs(folder.file(label), file, row.paper_resolution, k1);
    log(label + ": " + row.paper_resolution.solve.status + ", " +
        format_number("%.3g", row.paper_resolution.before.metrics.avg_root_force) + " -> " +
        format_number("%.3g N", row.paper_resolution.after.metrics.avg_root_force));
    if (!options.quick) {
      OptimizeOptions k3 = options.optimize;
      k3.nlp.knots_per_interval = 3;
      const OptimizationResult refined = optimize_motion(file.motion, file.model, k3);
      row.refined_run = true;
      row.refined_force_after = refined.after.metrics.avg_root_force;
      row.refined_iterations = refined.solve.iterations;
      row.refined_seconds = refined.solve.seconds;
      row.refined_status = refined.solve.status;
      log(label + ", K = 3: " + refined.solve.status + ", " +
          format_number("%.3g N", row.refined_force_after));
    }
    rows.push_back(std::move(row));
  }

  // The 5 m dive (§6.2): keyframe times before and after (Fig. 9).
  std::ostringstream dive_md;
  for (const auto& [label, path] : dives) {
    const MotionFile file = load_motion_file(path.string());
    OptimizeOptions k1 = options.optimize;
    k1.nlp.knots_per_interval = 1;
    const OptimizationResult r = optimize_motion(file.motion, file.model, k1);
    write_optimization_outputs(folder.file(label), file, r, k1);
    log(label + ": " + r.solve.status);
    dive_md << "**" << file.motion.name << "** (`" << label << "/`): " << r.solve.status
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

  // Mass study on the hardest skill (§6.1, Fig. 8).
  std::string mass_md = "No M7 in " + options.motions_dir + ".\n";
  const auto m7 = std::find_if(loaded.begin(), loaded.end(),
                               [](const LabelledMotion& m) { return m.label == "M7"; });
  if (m7 != loaded.end()) {
    MassStudyOptions mass;
    mass.optimize = options.optimize;
    const MassStudyResult study = run_mass_study(m7->file, mass);
    write_mass_outputs(folder.file("mass"), m7->file, study, mass);
    mass_md = mass_study_markdown(study) +
              "\n![Joint loads, Table 2 against thigh +50 % (Fig. 8)](figures/mass_loads.png)\n";
    log("mass study done");
  }

  // Convergence study (§3.4's claim).
  ConvergenceStudyOptions convergence;
  convergence.optimize = options.optimize;
  std::vector<LabelledMotion> study_motions = loaded;
  // The paper's mass-parameter errors hit every segment alike; a single segment's error (the
  // right thigh, as in the mass study) also breaks the body's left-right symmetry.
  convergence.mass_segments = {"all", "thigh_r"};
  if (options.quick) {
    convergence.mass_segments = {"all"};
    study_motions = {loaded.front()};
    if (loaded.size() > 1) study_motions.push_back(loaded.back());
    convergence.epsilons = {10, 500};
    convergence.mass_errors = {-0.2, 0.0, 0.2};
    convergence.timing_errors = {0.0, 0.1};
  }
  const std::vector<StudyOutcome> outcomes = run_convergence_study(
      study_motions, convergence, [&](int done, int total, const StudyOutcome& o) {
        log("convergence " + std::to_string(done) + "/" + std::to_string(total) + ": " +
            o.study_case.motion + " " + formulation_label(o.study_case) + " " + o.status);
      });
  write_convergence_outputs(folder.file("convergence"), outcomes, convergence);

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
     << table1_markdown(rows) << "\n## Root force before and after (Figs. 4 and 5)\n\n"
     << root_force_figures(rows)
     << "## Mass parameters (§6.1, Fig. 8): M7 with Table 2 against thigh mass and inertia "
        "+50 %\n\n"
     << mass_md << "\n## Designing a 5 m dive by optimising keyframe times (§6.2, Fig. 9)\n\n"
     << (dives.empty() ? std::string("No dive motion in the folder.\n\n") : dive_md.str())
     << "## Convergence study (§3.4)\n\n"
     << convergence_markdown(outcomes) << "\nEvery case is in `convergence/convergence.csv`.\n";
  write_text(folder.file("report.md"), md.str());

  nlohmann::json result;
  result["format"] = "saltus-report/1";
  result["status"] = "completed";
  result["quick"] = options.quick;
  result["table1"] = nlohmann::json::array();
  for (const Table1Row& r : rows) {
    const OptimizationResult& o = r.paper_resolution;
    nlohmann::json row = {{"skill", r.label},
                          {"keyframes", r.keyframes},
                          {"variables", o.variables},
                          {"constraints", o.constraints},
                          {"status", o.solve.status},
                          {"iterations", o.solve.iterations},
                          {"seconds", o.solve.seconds},
                          {"objective_before", o.before.metrics.objective},
                          {"objective_after", o.after.metrics.objective},
                          {"avg_force_before_N", o.before.metrics.avg_root_force},
                          {"avg_force_after_N", o.after.metrics.avg_root_force}};
    row["avg_force_after_K3_N"] =
        r.refined_run ? nlohmann::json(r.refined_force_after) : nlohmann::json(nullptr);
    if (const PaperTableRow* p = paper_table1(r.label))
      row["paper_avg_force_after_N"] = p->force_after;
    result["table1"].push_back(row);
  }
  int solved = 0;
  for (const StudyOutcome& o : outcomes)
    solved += o.solved && o.study_case.formulation == Formulation::kRelaxed ? 1 : 0;
  int relaxed = 0;
  for (const StudyOutcome& o : outcomes)
    relaxed += o.study_case.formulation == Formulation::kRelaxed ? 1 : 0;
  result["convergence_relaxed_solved"] = solved;
  result["convergence_relaxed_cases"] = relaxed;
  write_text(folder.file("result.json"), result.dump(2) + "\n");
  folder.commit();
  return result;
}

}  // namespace saltus
