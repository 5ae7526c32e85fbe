#include "core/model_edit.h"

#include <nlohmann/json.hpp>
#include <stdexcept>

#include "saltus/formats/model_file.h"

namespace saltus::gui {

BodyModel model_with_mass_factors(const BodyModel& original, const std::vector<double>& factors,
                                  const std::string& name) {
  if (static_cast<int>(factors.size()) != original.size())
    throw std::invalid_argument("one mass factor per segment expected");
  BodyModel model = original;
  for (int i = 0; i < original.size(); ++i) {
    const double factor = factors[static_cast<std::size_t>(i)];
    if (factor == 1.0) continue;
    model = scale_segment_mass(model, original.segments[static_cast<std::size_t>(i)].name, factor);
  }
  if (!name.empty()) model.name = name;
  // The library's own validation, with its message naming the field.
  return parse_body_model(body_model_to_json(model), "the edited model \"" + model.name + "\"");
}

double mass_factor_for(const BodyModel& original, int segment, double mass_kg) {
  if (segment < 0 || segment >= original.size()) throw std::invalid_argument("no such segment");
  return mass_kg / original.segments[static_cast<std::size_t>(segment)].mass;
}

}  // namespace saltus::gui
