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

}  // namespace saltus
