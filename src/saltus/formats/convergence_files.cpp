#include "saltus/formats/convergence_files.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <sstream>

#include "saltus/base/input_error.h"
#include "saltus/base/json_reader.h"
#include "saltus/base/text_format.h"
#include "saltus/formats/output_folder.h"
#include "saltus/optim/option_table.h"

namespace saltus {

namespace {

double median(std::vector<double> values) {
  if (values.empty()) return std::nan("");
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

std::string mass_label(const StudyCase& c) {
  if (c.mass_error == 0.0) return "0 %";
  return format_number("%+.0f %%", 100.0 * c.mass_error) + " (" + c.mass_segment + ")";
}

std::string timing_label(const StudyCase& c) {
  return c.timing_error_s == 0.0 ? "0 s" : format_number("±%.2f s", c.timing_error_s);
}

/// Success-rate table: one row per value of `row_of`, one column per formulation.
std::string success_table(const std::vector<StudyOutcome>& outcomes, const std::string& heading,
                          const std::function<std::string(const StudyCase&)>& row_of) {
  std::vector<std::string> rows, columns;
  std::map<std::pair<std::string, std::string>, std::pair<int, int>> counts;  // solved, total
  for (const StudyOutcome& o : outcomes) {
    const std::string row = row_of(o.study_case), column = formulation_label(o.study_case);
    if (std::find(rows.begin(), rows.end(), row) == rows.end()) rows.push_back(row);
    if (std::find(columns.begin(), columns.end(), column) == columns.end())
      columns.push_back(column);
    auto& count = counts[{row, column}];
    count.first += o.solved ? 1 : 0;
    count.second += 1;
  }
  std::ostringstream out;
  out << "| " << heading << " |";
  for (const std::string& c : columns)
    out << ' ' << c << " |";
  out << "\n|---|";
  for (std::size_t i = 0; i < columns.size(); ++i)
    out << "---|";
  out << '\n';
  for (const std::string& r : rows) {
    out << "| " << r << " |";
    for (const std::string& c : columns) {
      const auto it = counts.find({r, c});
      if (it == counts.end()) {
        out << " – |";
        continue;
      }
      out << ' ' << it->second.first << '/' << it->second.second << " |";
    }
    out << '\n';
  }
  return out.str();
}

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

bool finished(const StudyOutcome& o) {
  return o.status != "crashed" && o.status != "timed_out";
}

/// The convergence part of a study definition (see convergence_definition).
struct DefinitionSettings {
  unsigned seed = 1;
  int samples = 0, max_iterations = 0;
  nlohmann::json knots_per_interval;  ///< a number, or "auto"
};

DefinitionSettings read_settings(const nlohmann::json& definition) {
  const JsonNode root(definition, "study.json", "/definition");
  DefinitionSettings s;
  s.seed = static_cast<unsigned>(root.at("seed").as_int());
  const JsonNode optimize = root.at("optimize");
  s.samples = optimize.at("samples").as_int();
  s.knots_per_interval = optimize.at("knots_per_interval").value();
  s.max_iterations = optimize.at("max_iterations").as_int();
  return s;
}

}  // namespace

std::vector<ConvergenceSummaryRow> convergence_summary(const std::vector<StudyOutcome>& outcomes) {
  std::vector<ConvergenceSummaryRow> rows;
  for (const StudyOutcome& o : outcomes) {
    const std::string label = formulation_label(o.study_case);
    if (std::none_of(rows.begin(), rows.end(),
                     [&](const ConvergenceSummaryRow& r) { return r.model == label; }))
      rows.push_back({label});
  }
  for (ConvergenceSummaryRow& row : rows) {
    std::vector<double> iterations, seconds, force;
    double worst = std::nan("");
    for (const StudyOutcome& o : outcomes) {
      if (formulation_label(o.study_case) != row.model) continue;
      ++row.cases;
      if (!finished(o)) continue;  // listed below the table
      iterations.push_back(o.iterations);
      seconds.push_back(o.seconds);
      force.push_back(o.avg_force_after);
      if (o.solved) {
        ++row.solved;
        worst = std::isnan(worst) ? o.avg_force_after : std::max(worst, o.avg_force_after);
      }
    }
    row.median_iterations = median(iterations);
    row.median_seconds = median(seconds);
    row.median_force_after_N = median(force);
    row.worst_force_after_N = worst;
  }
  return rows;
}

std::vector<std::string> convergence_summary_headings() {
  return {"model",
          "cases",
          "solved",
          "median iterations",
          "median time (s)",
          "median avg root force after (N)",
          "worst avg root force after, solved cases (N)"};
}

std::vector<std::string> convergence_summary_cells(const ConvergenceSummaryRow& row) {
  return {row.model,
          std::to_string(row.cases),
          std::to_string(row.solved) + " (" +
              format_number("%.0f", 100.0 * row.solved / std::max(row.cases, 1)) + " %)",
          format_number("%.0f", row.median_iterations),
          format_number("%.2f", row.median_seconds),
          format_number("%.3g", row.median_force_after_N),
          row.solved ? format_number("%.3g", row.worst_force_after_N) : std::string("–")};
}

std::string convergence_markdown(const std::vector<StudyOutcome>& outcomes) {
  std::ostringstream out;
  const std::vector<std::string> headings = convergence_summary_headings();
  out << "|";
  for (const std::string& h : headings)
    out << ' ' << h << " |";
  out << "\n|";
  for (std::size_t i = 0; i < headings.size(); ++i)
    out << "---|";
  out << '\n';
  for (const ConvergenceSummaryRow& row : convergence_summary(outcomes)) {
    out << "|";
    for (const std::string& cell : convergence_summary_cells(row))
      out << ' ' << cell << " |";
    out << '\n';
  }
  // Cases whose process crashed or ran out of time count as unsolved; their figures are not in
  // the medians.
  std::vector<std::string> unfinished;
  for (const StudyOutcome& o : outcomes)
    if (!finished(o)) unfinished.push_back(study_case_label(o.study_case) + " (" + o.status + ")");
  if (!unfinished.empty()) {
    out << "\n"
        << unfinished.size()
        << " cases did not finish (their process crashed or ran out of time; see "
           "cases/): ";
    for (std::size_t i = 0; i < unfinished.size(); ++i)
      out << (i ? "; " : "") << unfinished[i];
    out << ".\n";
  }
  // Strict runs given up at a feasibility checkpoint (SolverOptions::feasibility_checkpoints).
  int stopped = 0;
  for (const StudyOutcome& o : outcomes)
    stopped += o.status == "stopped_infeasible" ? 1 : 0;
  if (stopped > 0)
    out << "\n"
        << stopped
        << " strict runs were stopped early (status stopped_infeasible): by a checkpoint of "
           "result.json's strict_checkpoints ([iterations, violation]) their constraint "
           "violation had not once come below its bound. They count as not solved.\n";
  // Cases whose interpolation could not meet the keyframes on the requested knots ran refined.
  std::map<std::string, int> refined;
  int requested = std::numeric_limits<int>::max();
  for (const StudyOutcome& o : outcomes)
    if (finished(o)) requested = std::min(requested, o.knots_per_interval);
  for (const StudyOutcome& o : outcomes)
    if (finished(o) && o.knots_per_interval > requested)
      ++refined[o.study_case.motion + format_number(" at ±%g s", o.study_case.timing_error_s)];
  if (!refined.empty()) {
    out << "\nRun with refined knots (K > " << requested
        << ") because the interpolation on the requested knots missed the keyframes by more than "
           "their tolerance (a turn of more than 180° between control points): ";
    bool first = true;
    for (const auto& [where, count] : refined) {
      out << (first ? "" : ", ") << where << " (" << count << " cases)";
      first = false;
    }
    out << ".\n";
  }
  out << "\nSolved cases by motion:\n\n"
      << success_table(outcomes, "motion", [](const StudyCase& c) { return c.motion; })
      << "\nSolved cases by mass-parameter error (masses and inertias scaled; segment in "
         "brackets):\n\n"
      << success_table(outcomes, "mass error", mass_label)
      << "\nSolved cases by keyframe-timing error (interior times moved by ± the amount, signs "
         "seeded):\n\n"
      << success_table(outcomes, "timing error", timing_label);
  return out.str();
}

std::string convergence_csv(const std::vector<StudyOutcome>& outcomes) {
  std::ostringstream out;
  out << "motion,formulation,epsilon,mass_segment,mass_error,timing_error_s,status,solved,"
         "iterations,seconds,variables,constraints,avg_force_before_N,avg_force_after_N,"
         "max_force_after_N,max_quaternion_error,knots_per_interval,restarts\n";
  out.precision(10);
  for (const StudyOutcome& o : outcomes) {
    const StudyCase& c = o.study_case;
    out << c.motion << ',' << (c.formulation == Formulation::kRelaxed ? "relaxed" : "strict") << ','
        << c.epsilon << ',' << c.mass_segment << ',' << c.mass_error << ',' << c.timing_error_s
        << ',' << o.status << ',' << (o.solved ? 1 : 0) << ',' << o.iterations << ',' << o.seconds
        << ',' << o.variables << ',' << o.constraints << ',' << o.avg_force_before << ','
        << o.avg_force_after << ',' << o.max_force_after << ',' << o.max_quaternion_error << ','
        << o.knots_per_interval << ',' << o.restarts << '\n';
  }
  return out.str();
}

nlohmann::json convergence_definition(const std::vector<LabelledMotion>& motions,
                                      const ConvergenceStudyOptions& options) {
  nlohmann::json list = nlohmann::json::array();
  for (const LabelledMotion& m : motions)
    list.push_back({{"label", m.label}, {"digest", motion_digest(m.file)}});
  return {{"motions", list},
          {"epsilons", options.epsilons},
          {"mass_errors", options.mass_errors},
          {"mass_segments", options.mass_segments},
          {"timing_errors", options.timing_errors},
          {"seed", options.seed},
          {"strict_checkpoints", checkpoints_json(options.strict_checkpoints)},
          {"optimize", result_deciding_settings(options.optimize)}};
}

const FolderKind& convergence_folder_kind() {
  static const FolderKind kind =
      study_folder_kind("study convergence", {"result.json", "convergence.csv", "convergence.md"});
  return kind;
}

nlohmann::json write_convergence_files(const std::string& dir,
                                       const std::vector<StudyOutcome>& outcomes,
                                       const nlohmann::json& definition) {
  const DefinitionSettings settings = read_settings(definition);
  std::filesystem::create_directories(dir);
  nlohmann::json result;
  result["format"] = "saltus-study/1";
  result["study"] = "convergence";
  result["status"] = "completed";
  result["seed"] = settings.seed;
  result["samples"] = settings.samples;
  result["knots_per_interval"] = settings.knots_per_interval;
  result["max_iterations"] = settings.max_iterations;
  result["strict_checkpoints"] =
      JsonNode(definition, "study.json", "/definition").at("strict_checkpoints").value();
  int failed = 0;
  result["cases"] = nlohmann::json::array();
  for (const StudyOutcome& o : outcomes) {
    result["cases"].push_back(outcome_json(o));
    failed += finished(o) ? 0 : 1;
  }
  result["failed"] = failed;
  const std::filesystem::path folder(dir);
  write_text((folder / "convergence.csv").string(), convergence_csv(outcomes));
  write_text((folder / "convergence.md").string(),
             "# Convergence study\n\n" + convergence_markdown(outcomes));
  write_text((folder / "result.json").string(), result.dump(2) + "\n");
  return result;
}

ConvergenceStudyFolder read_convergence_study_folder(const std::string& dir) {
  const StudyManifest manifest = read_study_manifest(dir);
  const std::string study_json = (std::filesystem::path(dir) / "study.json").string();
  if (manifest.study != "convergence")
    throw InputError(study_json, "/study",
                     "is \"" + manifest.study + "\", not a convergence study");
  if (!manifest.shard.whole())
    throw InputError(study_json, "/shard",
                     "is shard " + manifest.shard.text() +
                         " of a study; merge the shards first (saltus study merge)");
  ConvergenceStudyFolder folder;
  folder.path = dir;
  folder.cases = manifest.cases;
  for (const auto& [index, record] : read_case_records(dir, manifest.cases, nullptr)) {
    if (record.kind != CaseKind::kConvergence)
      throw InputError((std::filesystem::path(dir) / case_record_name(index)).string(), "/kind",
                       "not a case of a convergence study");
    folder.outcomes.push_back(record.convergence);
    folder.unfinished += finished(record.convergence) ? 0 : 1;
  }
  folder.summary = convergence_summary(folder.outcomes);
  const std::filesystem::path markdown = std::filesystem::path(dir) / "convergence.md";
  const std::filesystem::path csv = std::filesystem::path(dir) / "convergence.csv";
  if (std::filesystem::is_regular_file(markdown)) folder.markdown_path = markdown.string();
  if (std::filesystem::is_regular_file(csv)) folder.csv_path = csv.string();
  return folder;
}

}  // namespace saltus
