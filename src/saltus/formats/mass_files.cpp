#include "saltus/formats/mass_files.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iterator>
#include <map>
#include <sstream>

#include "saltus/base/input_error.h"
#include "saltus/base/json_reader.h"
#include "saltus/base/text_format.h"
#include "saltus/evaluation/joint_loads.h"
#include "saltus/formats/model_file.h"
#include "saltus/formats/output_folder.h"
#include "saltus/formats/result_json.h"

namespace saltus {

namespace {

/// The quantities of one run and segment in mass.csv, in column order.
const char* const kLoadColumns[8] = {"fx", "fy", "fz", "mx", "my", "mz", "force_N", "moment_Nm"};

/// Joint wrench (force first) of `segment` at every sample of an evaluation.
const Vector6d& load(const SampleRecord& sample, int segment) {
  return sample.joint_wrench.at(segment);
}

}  // namespace

std::string mass_study_csv(const MassStudyResult& study) {
  std::ostringstream out;
  out << 't';
  for (std::size_t r = 0; r < study.runs.size(); ++r)
    for (const std::string& s : study.load_segments)
      for (const char* q : kLoadColumns)
        out << ',' << kMassRunPrefixes.at(r) << '.' << s << '.' << q;
  out << '\n';
  out.precision(10);
  const std::size_t samples = study.runs.front().result.after.samples.size();
  for (std::size_t k = 0; k < samples; ++k) {
    out << study.runs.front().result.after.samples[k].time;
    for (const MassStudyRun& run : study.runs) {
      const SampleRecord& sample = run.result.after.samples.at(k);
      for (const std::string& s : study.load_segments) {
        const Vector6d& w = load(sample, run.model.segment_index(s));
        for (int i = 0; i < 6; ++i)
          out << ',' << w[i];
        out << ',' << w.head<3>().norm() << ',' << w.tail<3>().norm();
      }
    }
    out << '\n';
  }
  return out.str();
}

std::string mass_study_markdown(const MassStudyResult& study) {
  std::ostringstream out;
  out << "| model | segment | RMS force (N) | peak force (N) | input's peak (N) | RMS moment (N·m) "
         "| peak moment (N·m) | input's peak (N·m) | rise | avg root force after (N) |\n"
         "|---|---|---|---|---|---|---|---|---|---|\n";
  std::map<std::string, std::vector<double>> figures;  // segment -> per run RMS force, moment
  for (const MassStudyRun& run : study.runs) {
    const std::vector<JointLoadRise> rises =
        joint_load_rises(run.model, run.result.before.check, run.result.after.check);
    for (const std::string& s : study.load_segments) {
      const int index = run.model.segment_index(s);
      double force2 = 0, moment2 = 0;
      const auto& samples = run.result.after.samples;
      for (const SampleRecord& sample : samples) {
        const Vector6d& w = load(sample, index);
        force2 += w.head<3>().squaredNorm();
        moment2 += w.tail<3>().squaredNorm();
      }
      const double n = std::max<std::size_t>(samples.size(), 1);
      const double rms_force = std::sqrt(force2 / n), rms_moment = std::sqrt(moment2 / n);
      figures[s].push_back(rms_force);
      figures[s].push_back(rms_moment);
      // rises[k - 1] is segment k's joint (the root has none); peaks from the dense checks.
      const JointLoadRise rise = index >= 1 && index <= static_cast<int>(rises.size())
                                     ? rises[index - 1]
                                     : JointLoadRise{};
      out << "| " << run.label << " | " << s << " | " << format_number("%.1f", rms_force) << " | "
          << format_number("%.1f", rise.after.force_N) << " | "
          << format_number("%.1f", rise.before.force_N) << " | "
          << format_number("%.2f", rms_moment) << " | "
          << format_number("%.2f", rise.after.moment_Nm) << " | "
          << format_number("%.2f", rise.before.moment_Nm) << " | "
          << format_number("%.2fx", rise.ratio()) << " | "
          << format_number("%.3g", run.result.after.metrics.avg_root_force) << " |\n";
    }
  }
  out << "\nPeaks and rises from the dense checks; the input is the interpolated keyframes on the "
         "same model (the optimiser's starting point); rise: the larger of the force and moment "
         "ratios, peaks under "
      << format_number("%g N", kJointForceFloorN) << " or "
      << format_number("%g N·m", kJointMomentFloorNm)
      << " counted as those. RMS over mass.csv's samples.\n\nLargest rise over every joint:\n\n";
  for (const MassStudyRun& run : study.runs) {
    const JointLoadRise rise =
        largest_joint_load_rise(run.model, run.result.before.check, run.result.after.check);
    if (!rise.joint.empty())
      out << "- " << run.label << ": " << joint_load_rise_words(rise, body_weight_N(run.model))
          << "\n";
  }
  if (study.runs.size() == 2) {
    out << "\nScaled / given (RMS):\n\n| segment | force | moment |\n|---|---|---|\n";
    for (const std::string& s : study.load_segments) {
      const std::vector<double>& f = figures[s];
      out << "| " << s << " | " << format_number("%.2f", f[2] / f[0]) << " | "
          << format_number("%.2f", f[3] / f[1]) << " |\n";
    }
  }
  return out.str();
}

nlohmann::json mass_result_json(const MotionFile& file, const MassStudyResult& study,
                                const MassStudyOptions& options) {
  nlohmann::json result;
  result["format"] = "saltus-study/1";
  result["study"] = "mass";
  result["status"] = "completed";
  result["motion"] = file.motion.name;
  result["motion_file"] = file.path;
  result["factor"] = options.factor;
  result["scaled_segments"] = options.scaled_segments;
  result["load_segments"] = study.load_segments;
  result["protocol"] = options.paper_protocol ? "paper" : "optimize";
  result["runs"] = nlohmann::json::array();
  for (const MassStudyRun& run : study.runs) {
    const double weight = body_weight_N(run.model);
    nlohmann::json loads = nlohmann::json::object();
    for (const JointLoadRise& r :
         joint_load_rises(run.model, run.result.before.check, run.result.after.check))
      loads[r.joint] = {{"before", joint_peak_json(r.before, weight)},
                        {"after", joint_peak_json(r.after, weight)},
                        {"rise", r.ratio()}};
    const JointLoadRise largest =
        largest_joint_load_rise(run.model, run.result.before.check, run.result.after.check);
    result["runs"].push_back(
        {{"label", run.label},
         {"model", run.model.name},
         {"status", run.result.solve.status},
         {"iterations", run.result.solve.iterations},
         {"avg_force_before_N", run.result.before.metrics.avg_root_force},
         {"avg_force_after_N", run.result.after.metrics.avg_root_force},
         {"body_weight_N", weight},
         {"joint_loads", loads},
         {"largest_joint_rise", {{"joint", largest.joint}, {"rise", largest.ratio()}}}});
  }
  return result;
}

MassCsv read_mass_csv(const std::string& path) {
  return parse_mass_csv(read_csv_table(path), path);
}

MassCsv parse_mass_csv(const CsvTable& table, const std::string& file) {
  const std::vector<std::string>& columns = table.columns;
  const std::size_t per_segment = std::size(kLoadColumns);
  if (columns.empty() || columns[0] != "t" || (columns.size() - 1) % (2 * per_segment) != 0)
    throw InputError(file, "line 1",
                     "expected t, then per run (given, scaled) and load segment the columns "
                     "<run>.<segment>.fx ... moment_Nm");
  MassCsv out;
  out.time = table.column_values("t", file);
  const std::size_t segments = (columns.size() - 1) / (2 * per_segment);
  const std::string first_suffix = std::string(".") + kLoadColumns[0];
  for (std::size_t s = 0; s < segments; ++s) {
    // given.<segment>.fx names the segment; every other column must follow it.
    const std::string& first = columns[1 + s * per_segment];
    const std::string prefix = std::string(kMassRunPrefixes[0]) + ".";
    if (first.rfind(prefix, 0) != 0 || first.size() <= prefix.size() + first_suffix.size() ||
        first.compare(first.size() - first_suffix.size(), first_suffix.size(), first_suffix) != 0)
      throw InputError(file, "line 1",
                       "column " + std::to_string(2 + s * per_segment) + " is \"" + first +
                           "\", expected given.<segment>.fx");
    out.load_segments.push_back(
        first.substr(prefix.size(), first.size() - prefix.size() - first_suffix.size()));
  }
  for (const std::string& segment : out.load_segments) {
    std::array<MassLoads, 2> runs;
    for (std::size_t r = 0; r < 2; ++r) {
      const std::string stem = std::string(kMassRunPrefixes[r]) + "." + segment + ".";
      std::vector<std::vector<double>> values;
      for (const char* q : kLoadColumns)
        values.push_back(table.column_values(stem + q, file));
      MassLoads& loads = runs[r];
      for (std::size_t k = 0; k < out.time.size(); ++k) {
        Vector6d w;
        for (int i = 0; i < 6; ++i)
          w[i] = values[static_cast<std::size_t>(i)][k];
        loads.wrench.push_back(w);
      }
      loads.force_N = values[6];
      loads.moment_Nm = values[7];
    }
    out.loads.push_back(std::move(runs));
  }
  return out;
}

namespace {

std::vector<std::string> string_list(const JsonNode& node) {
  node.require_array();
  std::vector<std::string> list;
  for (std::size_t i = 0; i < node.size(); ++i)
    list.push_back(node.at(i).as_string());
  return list;
}

/// result.json of a mass study; the folder's path, name and mass.csv are left to the caller.
MassStudyFolder parse_mass_result(const nlohmann::json& document, const std::string& file) {
  const JsonNode root(document, file);
  root.require_object();
  if (root.at("study").as_string() != "mass")
    throw InputError(file, "/study", "not \"mass\" (not a `saltus study mass` folder)");
  MassStudyFolder out;
  out.motion = root.at("motion").as_string();
  out.motion_file = root.at("motion_file").as_string();
  out.factor = root.at("factor").as_double();
  out.scaled_segments = string_list(root.at("scaled_segments"));
  out.load_segments = string_list(root.at("load_segments"));
  const JsonNode runs = root.at("runs");
  runs.require_array();
  if (runs.size() != 2)
    throw InputError(file, runs.path_or_root(),
                     "expected two runs (given and scaled), found " + std::to_string(runs.size()));
  for (std::size_t r = 0; r < 2; ++r) {
    const JsonNode run = runs.at(r);
    MassStudyFolder::Run& to = out.runs[r];
    to.label = run.at("label").as_string();
    to.model = run.at("model").as_string();
    to.status = run.at("status").as_string();
    to.iterations = run.at("iterations").as_int();
    to.avg_force_before_N = run.at("avg_force_before_N").as_double();
    to.avg_force_after_N = run.at("avg_force_after_N").as_double();
  }
  return out;
}

}  // namespace

bool is_mass_study_folder(const std::string& dir) {
  return result_json_says(dir, "study", "mass");
}

MassStudyFolder read_mass_study_folder(const std::string& dir) {
  const std::string what = "a `saltus study mass` output folder";
  const std::string result_path = output_file(dir, "result.json", what);
  MassStudyFolder out = parse_mass_result(read_json_file(result_path), result_path);
  out.path = dir;
  out.name = folder_name(dir);
  const std::string csv = output_file(dir, "mass.csv", what);
  out.loads = read_mass_csv(csv);
  if (out.loads.load_segments != out.load_segments)
    throw InputError(csv, "line 1",
                     "its load segments differ from result.json's \"load_segments\"");
  return out;
}

}  // namespace saltus
