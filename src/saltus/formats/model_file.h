#pragma once
/// @file
/// Body model files, "saltus-model/1" (docs/formats.md, "Body model"): read, validated and written
/// here only.

#include <nlohmann/json_fwd.hpp>
#include <string>

#include "saltus/body/body_model.h"
#include "saltus/body/mass_properties.h"
#include "saltus/formats/output_kind.h"

namespace saltus {

/// The file's "format".
inline constexpr const char* kModelFormatTag = "saltus-model/1";

/// A model file Saltus writes on its own (`saltus model`, the app's Save model): a JSON kind,
/// marked (output_kind.h), so that only such a file is ever replaced; the model.json of a
/// result folder carries no mark.
const FileKind& model_file_kind();

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

/// Writes `model` to the file `path` through write_output_file (output_folder.h; missing parent
/// folders are created), so `path` is at every instant absent, the old file or the new complete
/// one, with Saltus's mark (model_file_kind()). An existing `path` is replaced only when it is a
/// model file Saltus wrote this way and nobody changed since; anything else (a model written by
/// hand, a result folder's model.json, another file, a folder, a symbolic link) is refused with
/// InputError naming `path`. OutputError when the system refuses (no permission, disk full);
/// nothing is changed then.
void save_body_model_file(const std::string& path, const BodyModel& model);

/// "saltus-model-info/1": what `saltus model info --json` prints (docs/formats.md, "Model
/// summary"): the model's name and source, total mass, standing height, whole-body CoM and
/// inertia about it in the standing pose, and per segment its name for people, mass (kg and %),
/// length, CoM and principal moments.
nlohmann::json model_summary_to_json(const ModelSummary& summary);

}  // namespace saltus
