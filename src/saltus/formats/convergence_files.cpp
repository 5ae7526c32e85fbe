#include "saltus/formats/convergence_files.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <sstream>

#include "saltus/base/text_format.h"
#include "saltus/formats/output_folder.h"

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

}  // namespace

std::string convergence_markdown(const std::vector<StudyOutcome>& outcomes) {
  std::ostringstream out;
  // Summary per formulation, in order of first appearance.
  std::vector<std::string> labels;
  for (const StudyOutcome& o : outcomes) {
    const std::string label = formulation_label(o.study_case);
    if (std::find(labels.begin(), labels.end(), label) == labels.end()) labels.push_back(label);
  }
  out << "| model | cases | solved | median iterations | median time (s) | median avg root force "
         "after (N) | worst avg root force after, solved cases (N) |\n"
      << "|---|---|---|---|---|---|---|\n";
  for (const std::string& label : labels) {
    int total = 0, solved = 0;
    std::vector<double> iterations, seconds, force;
    double worst = 0.0;
    for (const StudyOutcome& o : outcomes) {
      if (formulation_label(o.study_case) != label) continue;
      ++total;
      iterations.push_back(o.iterations);
      seconds.push_back(o.seconds);
      force.push_back(o.avg_force_after);
      if (o.solved) {
        ++solved;
        worst = std::max(worst, o.avg_force_after);
      }
    }
    out << "| " << label << " | " << total << " | " << solved << " ("
        << format_number("%.0f", 100.0 * solved / std::max(total, 1)) << " %) | "
        << format_number("%.0f", median(iterations)) << " | "
        << format_number("%.2f", median(seconds)) << " | " << format_number("%.3g", median(force))
        << " | " << (solved ? format_number("%.3g", worst) : std::string("–")) << " |\n";
  }
  // Cases whose interpolation could not meet the keyframes on the requested knots ran refined.
  std::map<std::string, int> refined;
  int requested = std::numeric_limits<int>::max();
  for (const StudyOutcome& o : outcomes)
    requested = std::min(requested, o.knots_per_interval);
  for (const StudyOutcome& o : outcomes)
    if (o.knots_per_interval > requested)
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

}  // namespace saltus
