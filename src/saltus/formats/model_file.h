#pragma once
/// @file
/// Body model files, "saltus-model/1" (docs/formats.md, "Body model"): read, validated and written
/// here only.

#include <nlohmann/json_fwd.hpp>
#include <string>

#include "saltus/body/body_model.h"

namespace saltus {

/// The file's "format".
inline constexpr const char* kModelFormatTag = "saltus-model/1";

/// Parses and validates a "saltus-model/1" document. `file` is used in error messages only.
/// Validation: format tag, unique segment and joint names, root first with parent null and joint
/// "root", every other parent named earlier in the list (so no cycles, topological order), finite
/// numbers, mass > 0, inertia 3 principal moments > 0 or 6 values forming a symmetric positive
/// definite matrix, shape sizes >= 0. A shape may list drawing "parts" (optional; files without
/// them read and write as before): {"name", "type": "ellipsoid", "center": [x, y, z], "radii":
/// [a, b, c]} or {"name", "type": "capsule", "center", "length", "radius"}, in segment
/// coordinates, sizes > 0. Throws InputError naming file and JSON path.
BodyModel parse_body_model(const nlohmann::json& document, const std::string& file);

/// Reads and validates a model file (see parse_body_model).
BodyModel load_body_model(const std::string& path);

/// Serialises to "saltus-model/1" (inertia written as 6 values). parse(to_json(m)) == m.
nlohmann::json body_model_to_json(const BodyModel& model);

}  // namespace saltus
