#include "saltus/use_cases/athlete_models.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "saltus/base/input_error.h"
#include "saltus/base/json_reader.h"
#include "saltus/base/resources.h"
#include "saltus/base/text_format.h"
#include "saltus/evaluation/flight_state.h"
#include "saltus/evaluation/rotation_metrics.h"
#include "saltus/evaluation/sampling.h"
#include "saltus/formats/model_file.h"
#include "saltus/formats/plausible_ranges.h"
#include "saltus/formats/yeadon_measurements_file.h"
#include "saltus/motion/interpolate.h"
#include "saltus/use_cases/captures.h"
#include "saltus/use_cases/flag_bounds.h"

namespace saltus {

namespace {

/// The model through the reader's checks (the same as every verb's), so a model that a verb
/// would refuse is never written.
BodyModel checked(const BodyModel& model) {
  return parse_body_model(body_model_to_json(model), model.name);
}

/// `name` (--name) as a model's name: UTF-8 text, as a model file holds it (JSON).
const std::string& checked_name(const std::string& name) {
  if (!is_valid_utf8(name))
    throw InputError("--name", "",
                     "\"" + message_text(name) +
                         "\" is not valid UTF-8 text; a model's name is written into its model "
                         "file, which is UTF-8 JSON");
  return name;
}

}  // namespace

Sex parse_sex(const std::string& text, const std::string& field) {
  if (text == "female") return Sex::kFemale;
  if (text == "male") return Sex::kMale;
  throw InputError(field, "", "expected \"female\" or \"male\", found \"" + text + "\"");
}

void check_person_size(double height_m, double mass_kg, const std::string& height_field,
                       const std::string& mass_field) {
  check_flag("--height", height_m, "", height_field);
  check_flag("--mass", mass_kg, "", mass_field);
  const double bmi = mass_kg / (height_m * height_m);
  if (!(bmi >= plausible::kMinBodyMassIndex && bmi <= plausible::kMaxBodyMassIndex))
    throw InputError(
        mass_field, "",
        message_number(mass_kg) + " kg at " + message_number(height_m) +
            " m is a body mass index of " +
            message_number_beside(bmi, plausible::kMinBodyMassIndex, plausible::kMaxBodyMassIndex) +
            " kg/m², outside the human range [" + message_number(plausible::kMinBodyMassIndex) +
            ", " + message_number(plausible::kMaxBodyMassIndex) +
            "]: is the height or the mass mistyped?");
}

StrengthSpec strength_from_flags(const std::string& reference, const std::string& sex,
                                 double age_years) {
  StrengthSpec spec;
  if (reference != "population" && reference != "elite-gymnast")
    throw InputError(
        "--strength", "",
        "expected population or elite-gymnast, found \"" + message_text(reference) + "\"");
  spec.reference = reference;
  spec.female = parse_sex(sex, "--sex") == Sex::kFemale;
  check_flag("--age", age_years);
  spec.age_years = age_years;
  return spec;
}

BodyModel new_athlete_model(const AthleteSize& size) {
  check_person_size(size.height_m, size.mass_kg, "--height", "--mass");
  checked_name(size.name);
  return checked(de_leva_model(size));
}

BodyModel load_model_argument(const std::string& model) {
  std::error_code ec;
  // Whatever is there (a folder, a pipe): the reader says what it is, not "no such file".
  if (std::filesystem::exists(model, ec)) return load_body_model(model);
  const std::string bundled =
      model.find('/') == std::string::npos ? resolve_model_path(model, "") : "";
  if (bundled.empty())
    throw InputError(model, "",
                     "no such model file, and no bundled model of that name under "
                     "resources/models/");
  return load_body_model(bundled);
}

BodyModel scaled_athlete_model(const BodyModel& model, double height_m, double mass_kg,
                               const std::string& name) {
  check_person_size(height_m, mass_kg, "--height", "--mass");
  std::string scaled_name = checked_name(name);
  const double height = standing_body(model).height();
  if (!(height > 0.0))
    throw InputError(model.name, "",
                     "the model has no standing height (no drawing shapes or joint offsets "
                     "along its segments), so it cannot be scaled to a height");
  if (scaled_name.empty()) {
    char text[64];
    std::snprintf(text, sizeof text, "-%.2fm-%.1fkg", height_m, mass_kg);
    scaled_name = model.name + text;
  }
  return checked(
      scale_body_model(model, height_m / height, mass_kg / model.total_mass(), scaled_name));
}

namespace {

/// The flags of `model yeadon` checked, before any file is read.
YeadonInput yeadon_flags(const std::string& densities, std::optional<double> mass_kg,
                         const std::string& name) {
  YeadonInput input;
  if (densities == "dempster")
    input.densities = YeadonDensities::kDempster;
  else if (densities == "chandler")
    input.densities = YeadonDensities::kChandler;
  else if (densities == "clauser")
    input.densities = YeadonDensities::kClauser;
  else
    throw InputError("--densities", "",
                     "expected dempster, chandler or clauser, found \"" + densities + "\"");
  if (mass_kg) check_flag("--mass", *mass_kg, "model yeadon");
  input.name = checked_name(name);
  input.total_mass = mass_kg.value_or(0.0);
  return input;
}

/// Yeadon's model of `file`'s measurements (read from `path`) with the checked flags `input`.
YeadonModel yeadon_model_of(YeadonInput input, const YeadonMeasurementsFile& file,
                            const std::string& path) {
  input.file = path;
  input.measured = file.measured;
  if (!(input.total_mass > 0.0)) input.total_mass = file.total_mass;
  if (input.name.empty()) input.name = std::filesystem::path(path).stem().string();
  YeadonModel out = yeadon_model(input);
  const StandingBody standing = standing_body(out.model);
  // A mass given was checked as given: the densities scaled to it sum to it only to rounding
  // (300 kg gave 300.00000000000006).
  check_person_size(standing.height(),
                    input.total_mass > 0.0 ? input.total_mass : out.model.total_mass(),
                    path + " (the standing height it gives)",
                    path + (input.total_mass > 0.0 ? " (--mass or totalmass)"
                                                   : " (the mass its densities give)"));
  out.model = checked(out.model);
  return out;
}

}  // namespace

YeadonModel yeadon_athlete_model(const std::string& path, const std::string& densities,
                                 std::optional<double> mass_kg, const std::string& name) {
  const YeadonInput input = yeadon_flags(densities, mass_kg, name);
  return yeadon_model_of(input, load_yeadon_measurements(path), path);
}

YeadonModel yeadon_athlete_model_of_text(const std::string& text, const std::string& path,
                                         const std::string& densities,
                                         std::optional<double> mass_kg, const std::string& name) {
  const YeadonInput input = yeadon_flags(densities, mass_kg, name);
  return yeadon_model_of(input, parse_yeadon_measurements(text, path), path);
}

YeadonModel yeadon_athlete_model(const std::string& path, const std::string& densities,
                                 double mass_kg, const std::string& name) {
  return yeadon_athlete_model(path, densities,
                              mass_kg == 0.0 ? std::nullopt : std::optional<double>(mass_kg), name);
}

void write_athlete_model(const std::string& path, const BodyModel& model) {
  save_body_model_file(path, model);
}

TakeoffRule parse_takeoff_rule(const std::string& text, const std::string& field) {
  if (text == "same-spin") return TakeoffRule::kSameSpin;
  if (text == "keep-momentum") return TakeoffRule::kKeepMomentum;
  throw InputError(
      field, "", "\"" + printable(text) + "\" is not a take-off rule: same-spin or keep-momentum");
}

MotionFile load_motion_for_athlete(const std::string& path, const std::string& model_override,
                                   TakeoffRule rule, const CaptureFileOptions& capture_options) {
  if (model_override.empty()) return load_motion_or_capture(path, "", capture_options);
  // The motion's own take-off is checked on its own body; on this athlete, the take-off it flies
  // (adapt_takeoff_to_athlete): a small athlete spins a big one's L far faster than same-spin.
  MotionFile athlete =
      load_motion_or_capture(path, model_override, capture_options, SpinCheck::kByCaller);
  return adapt_takeoff_to_athlete(load_motion_or_capture(path, "", capture_options),
                                  std::move(athlete), rule);
}

MotionFile adapt_takeoff_to_athlete(const MotionFile& own, MotionFile athlete, TakeoffRule rule) {
  // Only poses are needed (no dense residual check): the take-off pose for the inertias, and the
  // flight on a uniform grid when the motion gives no L to fit one from.
  const Trajectory<double> own_trajectory = motion_trajectory(own.motion, own.model);
  const auto own_samples = [&](const std::vector<double>& times) {
    return evaluate_trajectory(own.model, own_trajectory, times);
  };
  TakeoffAdaptation adaptation;
  adaptation.own_model = own.model.name;
  adaptation.own_angular_momentum =
      own.motion.takeoff.angular_momentum
          ? *own.motion.takeoff.angular_momentum
          : fit_flight_state(own_samples(uniform_times(own.motion.flight_time(), kDefaultSamples)))
                .angular_momentum;
  if (rule == TakeoffRule::kKeepMomentum) {
    adaptation.rule = "same angular momentum";
    adaptation.angular_momentum = adaptation.own_angular_momentum;
  } else {
    adaptation.rule = "same spin";
    const Eigen::Matrix3d own_inertia =
        whole_body_inertia_about_com(own.model, own_samples({0.0}).front());
    const Eigen::Matrix3d athlete_inertia = whole_body_inertia_about_com(
        athlete.model,
        evaluate_trajectory(athlete.model, motion_trajectory(athlete.motion, athlete.model), {0.0})
            .front());
    adaptation.angular_momentum =
        athlete_inertia * own_inertia.ldlt().solve(adaptation.own_angular_momentum);
  }
  athlete.motion.takeoff.angular_momentum = adaptation.angular_momentum;
  check_takeoff_spin(
      athlete.motion, athlete.model, athlete.path,
      rule == TakeoffRule::kSameSpin
          ? "the same-spin take-off on this athlete (from model \"" + own.model.name + "\"'s)"
          : "the take-off angular momentum kept from model \"" + own.model.name + "\"");
  athlete.takeoff_adaptation = adaptation;
  return athlete;
}

}  // namespace saltus
