// libFuzzer target: a BVH capture's text, imported onto the bundled model as `saltus import`
// imports it with its defaults (retargeting by joint names, the flight found from the feet,
// keyframes picked automatically). Bad input must end in InputError (exit 2); an accepted
// capture must give two motion files (the captured flight, the picked keyframes) whose text the
// motion reader reads back with the same keyframe times, and a result.json and trajectory.csv of
// finite numbers. Anything else (another exception, a crash, a sanitizer report, more than the
// limits' time or memory) is a finding.

#include <cstdint>
#include <cstdlib>
#include <string>

#include "saltus/base/input_error.h"
#include "saltus/base/json_reader.h"
#include "saltus/formats/bvh_file.h"
#include "saltus/formats/finite_check.h"
#include "saltus/formats/model_file.h"
#include "saltus/formats/motion_file.h"
#include "saltus/use_cases/captures.h"

namespace {

/// Inputs are bounded so that one stays far below libFuzzer's timeout: an import's cost is its
/// flight's frames, each a keyframe candidate (the greedy pick refits every curve through the
/// picked frames, K² fits). Under ASan and the fuzzer's instrumentation an import runs about 45
/// times slower than in a release build: the bundled DeepMimic clip takes 2 s; 12 flight frames
/// of random joint angles, all picked, 6.6 s (0.16 s in release); 16 such frames 11 s, 24 23 s,
/// 48 104 s. Larger texts and clips of more frames are skipped; the BVH reader's own bounds are
/// fuzzed by fuzz_bvh_file.
constexpr std::size_t kMaxImportBytes = 16u * 1024u;
constexpr int kMaxImportFrames = 12;

const saltus::BodyModel& bundled_model() {
  static const saltus::BodyModel model = saltus::load_body_model(
      std::string(SALTUS_RESOURCES_DIR) + "/models/" + saltus::kDefaultCaptureModel + ".json");
  return model;
}

/// A motion file as `import` writes it, read back as every verb reads it: from its text.
void require_reads_back(const saltus::Motion& imported, const nlohmann::json& document,
                        const std::string& name) {
  saltus::Motion back;
  try {
    back = saltus::parse_motion(saltus::parse_json_text(document.dump(2) + "\n", name), name,
                                bundled_model());
  } catch (const saltus::InputError&) {
    std::abort();  // import_capture_text accepted a flight it writes as an unreadable motion
  }
  if (back.keyframes.size() != imported.keyframes.size()) std::abort();
  for (std::size_t k = 0; k < back.keyframes.size(); ++k)
    if (back.keyframes[k].time != imported.keyframes[k].time) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > kMaxImportBytes) return 0;
  const std::string text(reinterpret_cast<const char*>(data), size);
  saltus::CaptureFile capture;
  try {
    if (saltus::parse_bvh(text, "fuzz.bvh").frame_count() > kMaxImportFrames) return 0;
    capture = saltus::import_capture_text(text, "fuzz.bvh", bundled_model());
  } catch (const saltus::InputError&) {
    return 0;
  }
  // What write_capture_outputs writes, checked as a reader of the folder would check it.
  try {
    saltus::require_finite(saltus::capture_result_json(capture), capture.path);
    saltus::require_finite(capture.import.samples, capture.path, "trajectory.csv");
  } catch (const saltus::InputError&) {
    std::abort();  // accepted, yet the result or trajectory.csv holds a non-finite number
  }
  require_reads_back(capture.import.captured, saltus::captured_motion_json(capture, "model.json"),
                     "capture.motion.json");
  require_reads_back(capture.import.keyframes, saltus::keyframes_motion_json(capture, "model.json"),
                     "keyframes.motion.json");
  return 0;
}
