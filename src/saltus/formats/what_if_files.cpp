#include "saltus/formats/what_if_files.h"

#include <sstream>
#include <stdexcept>

#include "saltus/base/constants.h"
#include "saltus/formats/twist_files.h"

namespace saltus {

nlohmann::json tuck_json(const TuckPhases& t) {
  if (!t.found) return {{"found", false}, {"reason", t.reason}};
  return {{"found", true},
          {"takeoff_bend_deg", t.takeoff_bend_deg},
          {"peak_bend_deg", t.peak_bend_deg},
          {"peak_time_s", t.peak_time_s},
          {"landing_bend_deg", t.landing_bend_deg},
          {"tuck_start_s", t.tuck_start_s},
          {"tucked_s", t.tucked_s},
          {"opens", t.opens},
          {"open_start_s", t.open_start_s},
          {"opened_s", t.opened_s},
          {"tuck_later_range_s", {t.tuck_later_min_s, t.tuck_later_max_s}},
          {"open_later_range_s", {t.open_later_min_s, t.open_later_max_s}}};
}

namespace {

nlohmann::json counts_json(const YeadonSummary& s) {
  return {{"somersaults", s.somersaults}, {"twists", s.twists}, {"description", s.description}};
}

/// Yeadon's angles (degrees, φ and ψ continuous) of a flight's samples.
std::vector<Eigen::Vector3d> angles_deg(const SimulationResult& flight) {
  std::vector<Eigen::Quaterniond> roots;
  for (const SampleRecord& s : flight.samples)
    roots.push_back(s.segment_rotation.at(0));
  std::vector<Eigen::Vector3d> out = unwrapped_angles(roots);
  for (Eigen::Vector3d& a : out)
    a *= kDegreesPerRadian;
  return out;
}

}  // namespace

nlohmann::json what_if_result_json(const MotionFile& file, const WhatIf& prepared,
                                   const WhatIfResult& r) {
  const Eigen::Vector3d& l = prepared.angular_momentum();
  return {{"format", kAnalysisFormat},
          {"analysis", "what-if"},
          {"motion", file.motion.name},
          {"motion_file", file.path},
          {"model", file.model.name},
          {"flight_time_s", file.motion.flight_time()},
          {"takeoff_angular_momentum", {l.x(), l.y(), l.z()}},
          {"change",
           {{"tuck_later_s", r.change.tuck_later_s},
            {"open_later_s", r.change.open_later_s},
            {"tuck_scale", r.change.tuck_scale}}},
          {"change_words", r.change_words},
          {"tuck", tuck_json(prepared.tuck())},
          {"changed_tuck", tuck_json(r.tuck)},
          {"landing", counts_json(r.landing)},
          {"as_is", counts_json(prepared.unchanged_landing())},
          {"keyframed", counts_json(prepared.target())},
          {"somersault_over_deg", r.somersault_over_deg},
          {"twist_over_deg", r.twist_over_deg},
          {"somersault_vs_as_is_deg", r.somersault_vs_unchanged_deg},
          {"twist_vs_as_is_deg", r.twist_vs_unchanged_deg},
          {"tolerance_deg", r.tolerance_deg},
          {"within_tolerance", r.within_tolerance},
          {"verdict", r.verdict},
          {"sentence", r.sentence}};
}

std::string what_if_csv(const WhatIf& prepared, const WhatIfResult& r) {
  const std::vector<Eigen::Vector3d> changed = angles_deg(r.flight);
  const std::vector<Eigen::Vector3d> as_is = angles_deg(prepared.unchanged());
  if (changed.size() != as_is.size())
    throw std::invalid_argument("the what-if flight and the flight as it is have other samples");
  std::ostringstream out;
  out << "t,what_if_somersault_deg,what_if_tilt_deg,what_if_twist_deg,as_is_somersault_deg,"
         "as_is_tilt_deg,as_is_twist_deg\n";
  out.precision(10);
  for (std::size_t k = 0; k < changed.size(); ++k)
    out << r.flight.samples[k].time << ',' << changed[k].x() << ',' << changed[k].y() << ','
        << changed[k].z() << ',' << as_is[k].x() << ',' << as_is[k].y() << ',' << as_is[k].z()
        << '\n';
  return out.str();
}

}  // namespace saltus
