#include "saltus/formats/athletes_files.h"

#include <filesystem>
#include <sstream>

#include "saltus/base/input_error.h"
#include "saltus/base/json_reader.h"
#include "saltus/base/text_format.h"
#include "saltus/evaluation/joint_loads.h"
#include "saltus/formats/output_folder.h"
#include "saltus/formats/study_folder.h"
#include "saltus/formats/table_cells.h"
#include "saltus/optim/option_table.h"

namespace saltus {

namespace {

/// Data files keep ten significant digits: enough to compare with a result.json, short to read.
std::string data(double value) {
  return format_number("%.10g", value);
}

std::string turns(double somersaults, double twists) {
  return format_number("%+.2f", somersaults) + " / " + format_number("%+.2f", twists);
}

/// "1.30x (hip_l)", flagged "not the athlete's" above kJointLoadRiseLimit; "—" when unknown.
std::string rise_words(const AthleteOutcome& o) {
  if (o.joint_rise <= 0.0) return "—";
  return format_number("%.2fx", o.joint_rise) + " (" + markdown_cell(o.joint_rise_joint) + ")" +
         (o.joint_rise > kJointLoadRiseLimit ? ", not the athlete's" : "");
}

}  // namespace

const FolderKind& athletes_folder_kind() {
  static const FolderKind kind =
      study_folder_kind("study athletes", {"result.json", "athletes.csv", "athletes.md"});
  return kind;
}

nlohmann::json athletes_definition(const std::string& motion_label, const MotionFile& own,
                                   const std::string& takeoff_rule,
                                   const std::vector<AthleteEntry>& athletes,
                                   const OptimizeOptions& options) {
  nlohmann::json list = nlohmann::json::array();
  for (const AthleteEntry& a : athletes)
    list.push_back({{"name", a.name}, {"digest", a.digest}});
  return {{"motion", {{"label", motion_label}, {"digest", motion_digest(own)}}},
          {"takeoff", takeoff_rule},
          {"athletes", list},
          {"optimize", result_deciding_settings(options)}};
}

std::string athletes_markdown(const std::vector<CaseRecord>& records) {
  std::ostringstream out;
  out << "| athlete | mass (kg) | height (m) | take-off \\|L\\| (kg·m²/s) | avg root force before "
         "(N) | after (N) | optimisation | landing error as given (°) | optimised (°) | "
         "somersaults / twists as given | optimised | largest joint moment (N·m) | largest joint "
         "force (% body weight) | largest rise over the athlete's input |\n"
      << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const CaseRecord& r : records) {
    const AthleteOutcome& o = r.athlete;
    const std::string name =
        markdown_cell(o.athlete) + (o.takeoff == "own model" ? " (own model)" : "");
    if (!r.finished()) {
      out << "| " << name << " | " << format_number("%.1f", o.mass_kg) << " | "
          << format_number("%.3f", o.height_m) << " | did not finish: " << markdown_cell(r.failure)
          << " |||||||||||\n";
      continue;
    }
    out << "| " << name << " | " << format_number("%.1f", o.mass_kg) << " | "
        << format_number("%.3f", o.height_m) << " | "
        << format_number("%.1f", o.takeoff_angular_momentum.norm()) << " | "
        << format_number("%.3g", o.avg_root_force_before_N) << " | "
        << format_number("%.3g", o.avg_root_force_after_N) << " | " << markdown_cell(o.status)
        << ", " << o.iterations << " it. | " << format_number("%.1f", o.landing_error_before_deg)
        << " | " << format_number("%.1f", o.landing_error_after_deg) << " | "
        << turns(o.somersaults_before, o.twists_before) << " | "
        << turns(o.somersaults_after, o.twists_after) << " | "
        << format_number("%.0f", o.peak_moment_Nm) << " (" << markdown_cell(o.peak_moment_joint)
        << ") | " << format_number("%.0f", o.peak_force_pct_bw) << " ("
        << markdown_cell(o.peak_force_joint) << ") | " << rise_words(o) << " |\n";
  }
  return out.str();
}

std::string athletes_csv(const std::vector<CaseRecord>& records) {
  std::ostringstream out;
  out << "athlete,takeoff,mass_kg,height_m,takeoff_L_x,takeoff_L_y,takeoff_L_z,status,solved,"
         "iterations,seconds,avg_force_before_N,avg_force_after_N,max_force_after_N,"
         "landing_error_before_deg,landing_error_after_deg,somersaults_before,twists_before,"
         "somersaults_after,twists_after,peak_moment_joint,peak_moment_Nm,peak_force_joint,"
         "peak_force_N,peak_force_pct_bw,joint_rise_joint,joint_rise\n";
  for (const CaseRecord& r : records) {
    const AthleteOutcome& o = r.athlete;
    out << csv_field(o.athlete) << ',' << csv_field(o.takeoff) << ',' << data(o.mass_kg) << ','
        << data(o.height_m);
    if (!r.finished()) {
      out << ",,,," << csv_field(o.status) << ",0,,,,,,,,,,,,,,,,,,\n";
      continue;
    }
    const Eigen::Vector3d& l = o.takeoff_angular_momentum;
    out << ',' << data(l.x()) << ',' << data(l.y()) << ',' << data(l.z()) << ','
        << csv_field(o.status) << ',' << (o.solved ? 1 : 0) << ',' << o.iterations << ','
        << data(o.seconds) << ',' << data(o.avg_root_force_before_N) << ','
        << data(o.avg_root_force_after_N) << ',' << data(o.max_root_force_after_N) << ','
        << data(o.landing_error_before_deg) << ',' << data(o.landing_error_after_deg) << ','
        << data(o.somersaults_before) << ',' << data(o.twists_before) << ','
        << data(o.somersaults_after) << ',' << data(o.twists_after) << ','
        << csv_field(o.peak_moment_joint) << ',' << data(o.peak_moment_Nm) << ','
        << csv_field(o.peak_force_joint) << ',' << data(o.peak_force_N) << ','
        << data(o.peak_force_pct_bw) << ',' << csv_field(o.joint_rise_joint) << ','
        << data(o.joint_rise) << '\n';
  }
  return out.str();
}

nlohmann::json write_athletes_files(const std::string& dir, const std::vector<CaseRecord>& records,
                                    const nlohmann::json& definition) {
  for (const CaseRecord& r : records)
    if (r.kind != CaseKind::kAthlete)
      throw InputError(case_record_name(r.index), "/kind", "not a case of an athletes study");
  const JsonNode root(definition, "study.json", "/definition");
  const std::string motion = root.at("motion").at("label").as_string();
  const std::string takeoff = root.at("takeoff").as_string();
  std::filesystem::create_directories(dir);
  nlohmann::json result;
  result["format"] = "saltus-study/1";
  result["study"] = "athletes";
  result["status"] = "completed";
  result["motion"] = motion;
  result["takeoff"] = takeoff;
  result["optimize"] = root.at("optimize").value();
  int failed = 0;
  result["cases"] = nlohmann::json::array();
  for (const CaseRecord& r : records) {
    nlohmann::json c = case_record_to_json(r).at("athlete");
    c["failure"] = r.finished() ? nlohmann::json(nullptr) : nlohmann::json(r.failure);
    result["cases"].push_back(c);
    failed += r.finished() ? 0 : 1;
  }
  result["failed"] = failed;
  const std::filesystem::path folder(dir);
  write_text((folder / "athletes.csv").string(), athletes_csv(records));
  write_text((folder / "athletes.md").string(),
             "# " + printable(motion) + " on " + std::to_string(records.size()) +
                 " athletes\n\nTake-off: " + printable(takeoff) +
                 " (the motion's own model keeps its take-off). Root force: the true average "
                 "sqrt(J/6) (dense check). Free flights: the joint movements flown from the "
                 "take-off, whole-body orientation at landing against the last keyframe; "
                 "somersaults (> 0 forward) and twists (> 0 to the left) by Yeadon's angles. Joint "
                 "loads: the optimised motion's peaks, and the largest rise of a joint's peak over "
                 "the same athlete's interpolated input (above 1.5x the optimiser made that joint "
                 "pay for the root force: not the athlete's load).\n\n" +
                 athletes_markdown(records));
  write_text((folder / "result.json").string(), result.dump(2) + "\n");
  return result;
}

}  // namespace saltus
