#include "core/athletes.h"

#include <cstdio>
#include <exception>
#include <stdexcept>

#include "saltus/base/input_error.h"
#include "saltus/body/mass_properties.h"
#include "saltus/body/yeadon_model.h"
#include "saltus/use_cases/athlete_models.h"

namespace saltus::gui {

namespace {

/// The dialog's names for the fields the library's messages call by their flags.
std::string field_name(const std::string& flag) {
  if (flag == "--height") return "Height";
  if (flag == "--mass") return "Mass";
  if (flag == "--sex") return "Sex";
  if (flag == "--densities") return "Densities";
  return flag;
}

BodyModel model_of(const AthleteRequest& r, std::vector<std::string>* warnings) {
  if (r.source == AthleteRequest::Source::kYeadon) {
    if (r.measurements.empty())
      throw InputError("Measurements file", "", "choose a file of Yeadon's measurements");
    YeadonModel made = yeadon_athlete_model(r.measurements, r.densities, r.yeadon_mass_kg, r.name);
    *warnings = made.warnings;
    return made.model;
  }
  AthleteSize size;
  size.height_m = r.height_m;
  size.mass_kg = r.mass_kg;
  size.sex = parse_sex(r.sex, "Sex");
  size.name = r.name;
  // The dialog's field names in the messages, then the library's model (which checks again).
  check_person_size(size.height_m, size.mass_kg, "Height", "Mass");
  return new_athlete_model(size);
}

}  // namespace

AthleteDraft draft_athlete(const AthleteRequest& request) {
  AthleteDraft out;
  try {
    out.model = model_of(request, &out.warnings);
  } catch (const InputError& e) {
    out.problem = InputError(field_name(e.file()), e.json_path(), e.problem()).what();
  } catch (const std::exception& e) {
    out.problem = e.what();
  }
  return out;
}

std::vector<std::string> yeadon_density_names() {
  return {yeadon_densities_name(YeadonDensities::kDempster),
          yeadon_densities_name(YeadonDensities::kChandler),
          yeadon_densities_name(YeadonDensities::kClauser)};
}

std::string athlete_figures(const BodyModel& model) {
  const ModelSummary s = summarize_model(model);
  const Eigen::Matrix3d& I = s.standing.body.inertia;
  char text[256];
  std::snprintf(text, sizeof text,
                "%.1f kg · standing height %.3f m · moments of inertia standing %.2f kg·m² "
                "somersault (x), %.2f twist (y), %.2f cartwheel (z)",
                s.total_mass, s.standing.height(), I(0, 0), I(1, 1), I(2, 2));
  return text;
}

std::string athlete_size(const BodyModel& model) {
  char size[64];
  std::snprintf(size, sizeof size, "%.2f m %.3g kg", standing_body(model).height(),
                model.total_mass());
  return size;
}

std::string athlete_label(const MotionFile& file) {
  std::string label = file.model.name + " " + athlete_size(file.model);
  if (file.takeoff_adaptation) {
    // "same spin" -> "same take-off spin", "same angular momentum" -> "same take-off ...".
    const std::string& rule = file.takeoff_adaptation->rule;
    const std::string same = "same ";
    label += ", " + (rule.rfind(same, 0) == 0 ? same + "take-off " + rule.substr(same.size())
                                              : "take-off: " + rule);
  }
  return label;
}

MotionFile motion_on_athlete(const MotionFile& own, const BodyModel& athlete) {
  if (athlete.size() != own.model.size())
    throw std::invalid_argument("the athlete's model has " + std::to_string(athlete.size()) +
                                " segments, the motion's " + std::to_string(own.model.size()));
  MotionFile on = own;
  on.model = athlete;
  on.takeoff_adaptation.reset();
  return adapt_takeoff_to_athlete(own, std::move(on), TakeoffRule::kSameSpin);
}

}  // namespace saltus::gui
