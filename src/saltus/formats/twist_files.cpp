#include "saltus/formats/twist_files.h"

#include <sstream>

#include "saltus/base/input_error.h"
#include "saltus/base/json_reader.h"
#include "saltus/base/text_format.h"
#include "saltus/formats/csv_table.h"
#include "saltus/formats/result_json.h"

namespace saltus {

namespace {

/// "without left arm" -> "without_left_arm".
std::string column_name(std::string name) {
  for (char& c : name)
    if (c == ' ' || c == '-') c = '_';
  return name;
}

}  // namespace

nlohmann::json twist_result_json(const MotionFile& file, const TwistSources& s) {
  nlohmann::json shares = nlohmann::json::array();
  for (const TwistShare& share : s.shares)
    shares.push_back(
        {{"source", share.source}, {"tilt_deg", share.tilt_deg}, {"percent", share.percent}});
  return {{"format", kAnalysisFormat},
          {"analysis", "twist"},
          {"motion", file.motion.name},
          {"motion_file", file.path},
          {"model", file.model.name},
          {"flight_time_s", file.motion.flight_time()},
          {"reference_time_s", s.reference_time_s},
          {"total_tilt_deg", s.total_tilt_deg},
          {"twists", s.twists},
          {"shares", shares},
          {"interaction_deg", s.interaction_deg},
          {"sentence", s.sentence}};
}

std::string twist_csv(const TwistSources& s) {
  std::ostringstream out;
  out << 't';
  for (const std::string& name : s.flight_names)
    out << ',' << column_name(name) << "_tilt_deg";
  out << '\n';
  out.precision(10);
  for (std::size_t k = 0; k < s.times.size(); ++k) {
    out << s.times[k];
    for (const std::vector<double>& tilt : s.tilt_deg)
      out << ',' << tilt[k];
    out << '\n';
  }
  return out.str();
}

std::string twist_markdown(const MotionFile& file, const TwistSources& s) {
  std::ostringstream out;
  out << "# Where the twist comes from: " << file.motion.name << "\n\n"
      << s.sentence << "\n\n"
      << format_number("Tilt of the free flight at mid-flight (t = %.3f s): ", s.reference_time_s)
      << format_number("%.1f°; ", s.total_tilt_deg) << format_number("%.2f twists", s.twists)
      << " over the flight.\n\n| source | tilt at mid-flight (°) | share |\n|---|---|---|\n";
  for (const TwistShare& share : s.shares)
    out << "| " << share.source << " | " << format_number("%.1f", share.tilt_deg) << " | "
        << format_number("%.0f %%", share.percent) << " |\n";
  out << "| total | " << format_number("%.1f", s.total_tilt_deg) << " | 100 % |\n"
      << "\nA movement is taken away by replacing it with its symmetric part (an arm by the mean "
         "of itself and the other arm's mirror image, legs and trunk likewise), every flight from "
         "the same take-off state (Yeadon's counterfactual free flights). The take-off's share is "
         "the tilt of the flight with every movement made symmetric; each movement's share is the "
         "tilt it adds, averaged over every order of taking the movements away (its Shapley "
         "value), so the shares add up to the total. An asymmetry between the two arms (one "
         "adducting while the other stays up) is shared between them: each arm's symmetric part "
         "removes half of it. The tilt over time of the actual flight, of the take-off alone and "
         "of each movement taken away alone is in twist.csv.\n";
  return out.str();
}

bool is_twist_analysis_folder(const std::string& dir) {
  return result_json_says(dir, "analysis", "twist");
}

TwistFolder read_twist_analysis_folder(const std::string& dir) {
  const std::string what = "a `saltus analyse twist` output folder";
  TwistFolder out;
  out.path = dir;
  out.name = folder_name(dir);
  const std::string result_path = output_file(dir, "result.json", what);
  const nlohmann::json document = read_json_file(result_path);
  const JsonNode root(document, result_path);
  root.require_object();
  if (root.at("format").as_string() != kAnalysisFormat)
    throw InputError(
        result_path, "/format",
        "not \"" + std::string(kAnalysisFormat) + "\" (a format this reader does not know)");
  if (root.at("analysis").as_string() != "twist")
    throw InputError(result_path, "/analysis",
                     "not \"twist\" (not a `saltus analyse twist` folder)");
  TwistSources& s = out.sources;
  out.motion = root.at("motion").as_string();
  s.reference_time_s = root.at("reference_time_s").as_double();
  s.total_tilt_deg = root.at("total_tilt_deg").as_double();
  s.twists = root.at("twists").as_double();
  s.interaction_deg = root.at("interaction_deg").as_double();
  s.sentence = root.at("sentence").as_string();
  const JsonNode shares = root.at("shares");
  shares.require_array();
  for (std::size_t i = 0; i < shares.size(); ++i) {
    const JsonNode share = shares.at(i);
    s.shares.push_back({share.at("source").as_string(), share.at("tilt_deg").as_double(),
                        share.at("percent").as_double()});
  }

  // twist.csv: t, then <flight>_tilt_deg per flight, named back as the library names them.
  const std::string csv_path = output_file(dir, "twist.csv", what);
  const CsvTable table = read_csv_table(csv_path);
  if (table.columns.size() < 2 || table.columns[0] != "t")
    throw InputError(csv_path, "line 1",
                     "expected t, then one <flight>_tilt_deg column per flight");
  std::vector<std::string> known = {"actual", "take-off only"};
  for (const TwistShare& share : s.shares)
    known.push_back("without " + share.source);
  s.times = table.column_values("t", csv_path);
  const std::string suffix = "_tilt_deg";
  for (std::size_t c = 1; c < table.columns.size(); ++c) {
    const std::string& column = table.columns[c];
    if (column.size() <= suffix.size() ||
        column.compare(column.size() - suffix.size(), suffix.size(), suffix) != 0)
      throw InputError(
          csv_path, "line 1",
          "column " + std::to_string(c + 1) + " is \"" + column + "\", expected <flight>_tilt_deg");
    const std::string stem = column.substr(0, column.size() - suffix.size());
    std::string name = stem;
    for (char& ch : name)
      if (ch == '_') ch = ' ';
    for (const std::string& k : known)
      if (column_name(k) == stem) name = k;
    s.flight_names.push_back(name);
    s.tilt_deg.push_back(table.column_values(column, csv_path));
  }
  return out;
}

}  // namespace saltus
