#include "saltus/formats/twist_files.h"

#include <sstream>

#include "saltus/base/text_format.h"

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
  out << "| together beyond their separate effects | " << format_number("%.1f", s.interaction_deg)
      << " | "
      << format_number("%.0f %%", std::abs(s.total_tilt_deg) > 1e-9
                                      ? 100.0 * s.interaction_deg / s.total_tilt_deg
                                      : 0.0)
      << " |\n\nEach aerial movement's share is the tilt lost when it is replaced by its "
         "symmetric part (an arm by the mean of itself and the other arm's mirror image, legs and "
         "trunk likewise); the take-off's is the tilt of the flight with every movement made "
         "symmetric, from the same take-off state (Yeadon's counterfactual free flights). The "
         "tilt over time of every flight is in twist.csv.\n";
  return out.str();
}

}  // namespace saltus
