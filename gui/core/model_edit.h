#pragma once
/// @file
/// Editing a body model's mass parameters: one scale factor per segment relative to the model as
/// loaded (mass and inertia together, the library's scale_segment_mass), checked by the
/// library's parser before the app uses it.

#include <string>
#include <vector>

#include "saltus/body/body_model.h"

namespace saltus::gui {

/// `original` with segment i's mass and inertia multiplied by factors[i] (one per segment, each
/// > 0), named `name` (kept if empty). Throws std::invalid_argument (a bad factor, the library's
/// message) or InputError (the library's parser rejects the result).
BodyModel model_with_mass_factors(const BodyModel& original, const std::vector<double>& factors,
                                  const std::string& name = "");

/// The factor that gives segment `segment` the mass `mass_kg`.
double mass_factor_for(const BodyModel& original, int segment, double mass_kg);

}  // namespace saltus::gui
