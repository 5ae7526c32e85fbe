#pragma once
/// @file
/// `saltus model new|info|scale` (and the app's New athlete): body models of particular
/// athletes, checked like any model file and written like every file Saltus writes.
/// docs/cli.md, "model"; the method in docs/method.md, "Athletes' body models".

#include <optional>
#include <string>

#include "saltus/body/athlete_model.h"
#include "saltus/body/body_model.h"
#include "saltus/body/mass_properties.h"
#include "saltus/body/yeadon_model.h"
#include "saltus/motion/motion.h"
#include "saltus/use_cases/captures.h"

namespace saltus {

/// "female" or "male"; anything else is InputError naming `field` (e.g. "--sex").
Sex parse_sex(const std::string& text, const std::string& field);

/// An athlete's strength from the model verbs' flags: `reference` "population" or
/// "elite-gymnast" (--strength), `sex` "female" or "male" (--sex), `age_years` within the
/// plausible range (--age); InputError naming the flag otherwise.
StrengthSpec strength_from_flags(const std::string& reference, const std::string& sex,
                                 double age_years);

/// Refuses, with InputError naming `height_field` or `mass_field`, a stature or a mass outside
/// the human range (formats/plausible_ranges.h) or a pair whose body mass index no person has.
void check_person_size(double height_m, double mass_kg, const std::string& height_field,
                       const std::string& mass_field);

/// de Leva's model of a person (de_leva_model), after check_person_size on "--height" and
/// "--mass" and a name of UTF-8 text ("--name"), and read back through the model reader's checks,
/// so every verb accepts it.
BodyModel new_athlete_model(const AthleteSize& size);

/// A model file's path, or a bundled model's name (resources/models/); InputError if neither.
BodyModel load_model_argument(const std::string& model);

/// `model` scaled to a person `height_m` tall (its standing height, standing_body) weighing
/// `mass_kg` (scale_body_model), after check_person_size; named `name` (UTF-8 text, else
/// InputError naming --name), or
/// "<model>-<H>m-<M>kg" when empty.
BodyModel scaled_athlete_model(const BodyModel& model, double height_m, double mass_kg,
                               const std::string& name);

/// Yeadon's model of the person measured in `path` (formats/yeadon_measurements_file.h):
/// `densities` "dempster", "chandler" or "clauser" (else InputError naming --densities);
/// `mass_kg`, when given, within the human range (else InputError naming --mass; 0 too), scales
/// every density so the body weighs it (else the file's `totalmass`, if any); named `name`
/// (UTF-8 text, else InputError naming --name), or the file's name without its extension. The
/// model must stand and weigh like a person (check_person_size, naming the file) and pass the
/// model reader.
YeadonModel yeadon_athlete_model(const std::string& path, const std::string& densities,
                                 std::optional<double> mass_kg, const std::string& name);
/// The same of a measurement file's text, as read from `path` (which names it in messages and
/// the model when `name` is empty): for text in memory (the fuzz target).
YeadonModel yeadon_athlete_model_of_text(const std::string& text, const std::string& path,
                                         const std::string& densities,
                                         std::optional<double> mass_kg, const std::string& name);
/// The same with `mass_kg` 0 for none (the app's "from the file"; `saltus model yeadon --mass 0`
/// is refused by the overload above).
YeadonModel yeadon_athlete_model(const std::string& path, const std::string& densities,
                                 double mass_kg, const std::string& name);

/// How a motion's take-off carries over to another athlete (`--takeoff`): the same whole-body
/// spin ω = I⁻¹·L at take-off, so the angular momentum follows the athlete's inertia (a coach's
/// "the same take-off, done by this athlete"), or the same angular momentum L.
enum class TakeoffRule { kSameSpin, kKeepMomentum };

/// "same-spin" or "keep-momentum"; anything else is InputError naming `field`.
TakeoffRule parse_takeoff_rule(const std::string& text, const std::string& field);

/// The motion (or capture) at `path` flown by the athlete `model_override` (a model file or a
/// bundled name; "" = the motion's own model, returned as loaded): the same keyframes, times and
/// take-off CoM position and velocity, and the take-off angular momentum by `rule`, from the
/// motion's own (its file's, or the constant nearest its L(t) on its own model): same spin,
/// L' = I'·I⁻¹·L with I, I' the whole-body inertias about the CoM in the first keyframe's pose.
/// The result's takeoff_adaptation says what was done (result.json "takeoff_adaptation"). A
/// capture is imported with `capture_options` on both models (the defaults of `saltus import`
/// unless given).
MotionFile load_motion_for_athlete(const std::string& path, const std::string& model_override,
                                   TakeoffRule rule,
                                   const CaptureFileOptions& capture_options = {});

/// load_motion_for_athlete's step after reading: `athlete`, the motion of `own` on another
/// athlete's model (the same keyframes, checked against that model), gets its take-off angular
/// momentum by `rule` from `own`'s and says so in takeoff_adaptation. For motions in memory (the
/// Python module).
MotionFile adapt_takeoff_to_athlete(const MotionFile& own, MotionFile athlete, TakeoffRule rule);

/// Writes a model file (save_body_model_file): atomic, never over a file Saltus did not write.
void write_athlete_model(const std::string& path, const BodyModel& model);

}  // namespace saltus
