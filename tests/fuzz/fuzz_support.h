#pragma once
// What several fuzz targets share: the bundled model, loaded once, the check that a BVH clip
// Saltus wrote reads back as it was written, and for the exports a fuzzed motion read against
// the bundled model and a text's numbers checked finite.

#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "saltus/base/input_error.h"
#include "saltus/base/json_reader.h"
#include "saltus/capture/mocap_clip.h"
#include "saltus/evaluation/evaluate.h"
#include "saltus/formats/finite_check.h"
#include "saltus/formats/model_file.h"
#include "saltus/formats/motion_file.h"
#include "saltus/use_cases/motion_exports.h"

namespace saltus::fuzz {

inline const BodyModel& bundled_model() {
  static const BodyModel model =
      load_body_model(std::string(SALTUS_RESOURCES_DIR) + "/models/zatsiorsky-66kg.json");
  return model;
}

/// M1's keyframes as their file holds them, read once: the motion a fuzzed athlete is flown on.
inline const nlohmann::json& m1_document() {
  static const nlohmann::json document = read_json_file(
      std::string(SALTUS_EXAMPLES_DIR) + "/motions/M1-straight-back-somersault.motion.json");
  return document;
}

/// M1's keyframes on an accepted fuzzed `model`: aborts (a finding) unless its inverse dynamics
/// are finite; keyframes that do not fit the model's joints (InputError) are no finding.
inline void abort_unless_m1_is_finite_on(const BodyModel& model) {
  Motion motion;
  try {
    motion = parse_motion(m1_document(), "m1.motion.json", model);
  } catch (const InputError&) {
    return;
  }
  EvaluateOptions options;
  options.samples = 9;
  const MotionEvaluation evaluation = evaluate_motion(motion, model, options);
  try {
    require_finite(evaluation.samples, "m1.motion.json", "trajectory.csv");
  } catch (const InputError&) {
    std::abort();
  }
}

/// Aborts (a finding) unless `back` has `clip`'s frames, frame time and skeleton.
inline void abort_unless_same_clip(const MocapClip& back, const MocapClip& clip) {
  if (back.frames != clip.frames || back.frame_time != clip.frame_time ||
      back.joint_count() != clip.joint_count())
    std::abort();
  for (int j = 0; j < clip.joint_count(); ++j)
    if (back.joints[j].name != clip.joints[j].name ||
        back.joints[j].parent != clip.joints[j].parent ||
        back.joints[j].offset != clip.joints[j].offset ||
        back.joints[j].channels != clip.joints[j].channels ||
        back.joints[j].end_sites != clip.joints[j].end_sites)
      std::abort();
}

/// The fuzzer's bytes as a motion file on the bundled model, or nothing when the reader refuses
/// them (InputError: bad input, exit 2). Named "fuzz": the text's numbers are what is checked,
/// a name of the input's (which the writers escape, tested elsewhere) would only blur that.
inline std::optional<MotionFile> fuzzed_motion(const std::uint8_t* data, std::size_t size) {
  if (size > kMaxJsonFileBytes) return std::nullopt;
  const std::string text(reinterpret_cast<const char*>(data), size);
  MotionFile source;
  source.path = "fuzz.motion.json";
  source.model = bundled_model();
  try {
    source.motion = parse_motion(parse_json_text(text, source.path), source.path, source.model);
  } catch (const InputError&) {
    return std::nullopt;
  }
  source.motion.name = "fuzz";
  return source;
}

/// The frame rate the export targets sample at: low, so that a long flight stays quick under the
/// sanitizers; the writers do the same per frame at any rate.
inline constexpr double kFuzzExportFps = 20.0;

/// A fuzzed motion exported in `format` at kFuzzExportFps, and its frame count; nothing when the
/// motion or its export is refused as bad input (InputError).
struct FuzzedExport {
  MotionFile source;
  std::vector<ExportFile> files;
  std::size_t frames = 0;
};
inline std::optional<FuzzedExport> fuzzed_export(const std::uint8_t* data, std::size_t size,
                                                 const std::string& format) {
  std::optional<MotionFile> source = fuzzed_motion(data, size);
  if (!source) return std::nullopt;
  FuzzedExport out;
  out.source = std::move(*source);
  try {
    out.files = export_files(out.source, format, kFuzzExportFps, "fuzz");
  } catch (const InputError&) {
    return std::nullopt;
  }
  out.frames =
      static_cast<std::size_t>(std::round(out.source.motion.flight_time() * kFuzzExportFps) + 1);
  return out;
}

/// Aborts (a finding) when `text` holds a number written as NaN or infinity: a word "nan",
/// "inf" or "infinity" (any case, any sign) between spaces, tabs, commas, quotes or brackets.
inline void abort_on_non_finite_word(const std::string& text) {
  std::string word;
  const auto check = [&word] {
    std::string w;
    for (char c : word)
      w.push_back(static_cast<char>(std::tolower(static_cast<unsigned char>(c))));
    if (!w.empty() && (w[0] == '-' || w[0] == '+')) w.erase(0, 1);
    if (w == "nan" || w == "inf" || w == "infinity") std::abort();
    word.clear();
  };
  for (char c : text) {
    if (std::isspace(static_cast<unsigned char>(c)) || c == ',' || c == '"' || c == '<' ||
        c == '>' || c == '[' || c == ']')
      check();
    else
      word.push_back(c);
  }
  check();
}

}  // namespace saltus::fuzz
