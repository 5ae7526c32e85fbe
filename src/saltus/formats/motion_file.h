#pragma once
/// @file
/// Motion files, "saltus-motion/1" (docs/formats.md, "Motion"): read, validated and written here
/// only.

#include <nlohmann/json_fwd.hpp>
#include <string>

#include "saltus/formats/output_kind.h"
#include "saltus/motion/motion.h"

namespace saltus {

/// The file's "format".
inline constexpr const char* kMotionFormatTag = "saltus-motion/1";

/// A motion file Saltus writes on its own (the app's Save motion): a JSON kind, marked
/// (output_kind.h), so that only such a file is ever replaced; the motions inside result
/// folders carry no mark.
const FileKind& motion_file_kind();

/// Whether reading a motion checks its take-off angular momentum on the model it is read with
/// (check_takeoff_spin), or leaves that to a caller that changes the take-off first (the motion
/// flown by another athlete: use_cases/athlete_models.h checks the take-off that athlete flies).
enum class SpinCheck { kOnLoad, kByCaller };

/// Parses and validates a "saltus-motion/1" document against `model` (every keyframe must give
/// every joint of the model, no unknown joints). `file` is used in messages. Normalises
/// quaternions off by at most 1e-3 in norm; rejects worse. Throws InputError naming file and
/// JSON path.
Motion parse_motion(const nlohmann::json& document, const std::string& file, const BodyModel& model,
                    SpinCheck spin = SpinCheck::kOnLoad);

/// Reads a motion file and the model it names (resolved by resolve_model_path). If
/// `model_override` is not empty it is used instead of the file's "model" field.
MotionFile load_motion_file(const std::string& path, const std::string& model_override = "",
                            SpinCheck spin = SpinCheck::kOnLoad);

/// Refuses a take-off angular momentum that would spin `model` implausibly fast: |I⁻¹·L| in the
/// first keyframe's pose beyond plausible::kMaxBodyAngularVelocity. InputError naming `file`
/// and /takeoff/angular_momentum; `whose` begins the message ("this angular momentum", "the
/// same-spin take-off on this athlete"). Nothing to check without an angular momentum.
void check_takeoff_spin(const Motion& motion, const BodyModel& model, const std::string& file,
                        const std::string& whose);

/// What the "model" field of a motion file saved at `motion_file` should say to name the model
/// file `model_file` so that reading it back finds that file: a bundled model's name (a file
/// directly under resources/models/), else the path relative to the motion file's folder.
/// `loads_by_itself` is false when that path leaves the folder: the reader refuses such
/// references, so the saved file then loads only with the model given (--model, Open model).
struct ModelReference {
  std::string field;
  bool loads_by_itself = true;
};
ModelReference model_reference_for(const std::string& model_file, const std::string& motion_file);

/// Serialises to "saltus-motion/1" (rotations as [w, x, y, z]; "spline" included when present).
nlohmann::json motion_to_json(const Motion& motion, const BodyModel& model);

/// Writes motion_to_json(motion, model) to `path` through write_output_file (output_folder.h):
/// at every instant `path` is absent, the old file or the new complete one, with Saltus's mark
/// (motion_file_kind()); an existing `path` is replaced only when it is a motion file Saltus
/// wrote this way and nobody changed since, anything else is refused with InputError naming it.
/// OutputError when the system refuses.
void save_motion_file(const std::string& path, const Motion& motion, const BodyModel& model);

/// The "model" field of a motion file, read without validating the rest (to find the model).
std::string read_motion_model_field(const nlohmann::json& document, const std::string& file);

/// Short label of a motion file for tables and folder names: "M3-tucked-double-back.motion.json"
/// -> "M3"; any other file: its name without ".motion.json".
std::string motion_label(const std::string& path);

}  // namespace saltus
