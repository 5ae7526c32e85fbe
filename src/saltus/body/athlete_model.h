#pragma once
/// @file
/// Body models of particular athletes: from stature, mass and sex through de Leva's table
/// (de_leva_table.h), and any model scaled to another stature and mass. The models have the
/// bundled model's 13 segments, joints and axes, so every motion runs on them. How de Leva's
/// segments map onto ours: docs/method.md, "Athletes' body models".

#include <string>

#include "saltus/body/body_model.h"
#include "saltus/body/de_leva_table.h"

namespace saltus {

/// Who the model is for.
struct AthleteSize {
  double height_m = 1.70;  ///< standing height (stature), m
  double mass_kg = 65.5;   ///< body mass, kg
  Sex sex = Sex::kMale;
  std::string name;  ///< the model's name; "" gives e.g. "de-leva-male-1.70m-65.5kg"
};

/// Drawing proportions of the bundled model (resources/models/zatsiorsky-66kg.json), a 1.70 m,
/// 65.5 kg athlete: widths and the shoulder and hip joint spacing are not in de Leva's table,
/// so they are taken from it, scaled with stature (joint spacing) or with the square root of
/// mass per length (drawing widths).
inline constexpr double kReferenceStature = 1.70;
inline constexpr double kReferenceMass = 65.5;
/// The shoulder and hip joint centres either side of the mid-line, fractions of stature.
inline constexpr double kShoulderHalfWidth = 0.18 / kReferenceStature;
inline constexpr double kHipHalfWidth = 0.085 / kReferenceStature;
/// The ankle joint centre above the sole, fraction of stature (Drillis & Contini).
inline constexpr double kAnkleHeight = 0.039;

/// The model of `size` from de Leva's Table 4: segment lengths are his mean lengths × H / his
/// mean stature, masses his fractions × M (divided by their sum, 1.0000 male, 0.9999 female),
/// CoMs and principal radii of gyration his fractions of each length; the head goes with the
/// thorax and each hand with its forearm, composed exactly (parallel-axis theorem). Standing at
/// identity it is exactly `height_m` tall. Throws std::invalid_argument for a non-positive size.
BodyModel de_leva_model(const AthleteSize& size);

/// The same model for a person `length_factor` times as tall and `mass_factor` times as heavy:
/// every length (joint positions, CoMs, drawing shapes) × length_factor, masses × mass_factor,
/// inertias × mass_factor · length_factor². Named `name`. Throws std::invalid_argument for
/// non-positive factors.
BodyModel scale_body_model(const BodyModel& model, double length_factor, double mass_factor,
                           const std::string& name);

}  // namespace saltus
