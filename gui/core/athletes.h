#pragma once
/// @file
/// Athletes in the app: the body model the New athlete dialog makes (the library's de Leva or
/// Yeadon model, checked as `saltus model new|yeadon` checks it), its figures in one line, and
/// how a run's athlete is named in the compare window ("junior 1.45 m 38 kg, same take-off
/// spin").

#include <optional>
#include <string>
#include <vector>

#include "saltus/body/body_model.h"
#include "saltus/motion/motion.h"

namespace saltus::gui {

/// What the New athlete dialog asks for.
struct AthleteRequest {
  enum class Source { kSize, kYeadon };
  Source source = Source::kSize;
  std::string name;  ///< "" gives the library's default name
  // kSize: a person's size, de Leva's model (`saltus model new`).
  double height_m = 0.0;
  double mass_kg = 0.0;
  std::string sex;  ///< "female" or "male" (parse_sex)
  // kYeadon: Yeadon's measurements (`saltus model yeadon`).
  std::string measurements;     ///< the file
  std::string densities;        ///< "dempster", "chandler" or "clauser"
  double yeadon_mass_kg = 0.0;  ///< > 0 scales the densities to it; 0: the file's own
};

/// The model of a request, or why there is none.
struct AthleteDraft {
  std::optional<BodyModel> model;
  /// The library's message when there is no model, naming the field ("Height: 3 m is
  /// outside [0.5, 2.8] m (the human range; ...)") or the file.
  std::string problem;
  std::vector<std::string> warnings;  ///< Yeadon's measurements that look wrong but are usable
};

/// The library's model (new_athlete_model, yeadon_athlete_model); never throws for bad input.
AthleteDraft draft_athlete(const AthleteRequest& request);

/// The density tables a Yeadon model can use, as the library names them.
std::vector<std::string> yeadon_density_names();

/// The model's figures standing (summarize_model), in one line: "38.0 kg · standing height
/// 1.450 m · moments of inertia 6.31 kg·m² somersault (x), 0.52 twist (y), 6.02 cartwheel (z)".
std::string athlete_figures(const BodyModel& model);

/// The model's standing height (standing_body) and mass: "1.45 m 38 kg".
std::string athlete_size(const BodyModel& model);

/// The open motion `own` flown by `athlete` (a model not saved yet, e.g. New athlete's): its
/// keyframes and take-off CoM state, the angular momentum carried over by the same spin, as
/// `saltus simulate --model` carries it (adapt_takeoff_to_athlete). std::invalid_argument when
/// the athlete's model has other segments than the motion's.
MotionFile motion_on_athlete(const MotionFile& own, const BodyModel& athlete);

/// Who flies the motion, for legends and titles: the model's name, standing height and mass,
/// and, when the motion was made for another athlete, the rule that carried its take-off over:
/// "junior 1.45 m 38 kg, same take-off spin".
std::string athlete_label(const MotionFile& file);

}  // namespace saltus::gui
