// libFuzzer target: a Yeadon measurement file's text made into an athlete's model as `saltus
// model yeadon` makes it (yeadon_athlete_model_of_text, Dempster's densities, the file's mass).
// Bad input must end in InputError; an accepted model must give finite inverse dynamics for M1's
// keyframes.

#include <cstdint>
#include <cstdlib>
#include <string>

#include "saltus/base/input_error.h"
#include "saltus/base/json_reader.h"
#include "saltus/evaluation/evaluate.h"
#include "saltus/formats/finite_check.h"
#include "saltus/formats/motion_file.h"
#include "saltus/use_cases/athlete_models.h"

namespace {

/// The reader's own limit (a measurement file is at most 1 MiB); the fuzzer's inputs are smaller.
constexpr std::size_t kMaxYeadonFuzzBytes = 1u << 20;

const nlohmann::json& m1_keyframes() {
  static const nlohmann::json document = saltus::read_json_file(
      std::string(SALTUS_EXAMPLES_DIR) + "/motions/M1-straight-back-somersault.motion.json");
  return document;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > kMaxYeadonFuzzBytes) return 0;
  const std::string text(reinterpret_cast<const char*>(data), size);
  saltus::BodyModel model;
  saltus::Motion motion;
  try {
    model =
        saltus::yeadon_athlete_model_of_text(text, "fuzz.txt", "dempster", std::nullopt, "").model;
    motion = saltus::parse_motion(m1_keyframes(), "m1.motion.json", model);
  } catch (const saltus::InputError&) {
    return 0;
  }
  saltus::EvaluateOptions options;
  options.samples = 9;
  const saltus::MotionEvaluation evaluation = saltus::evaluate_motion(motion, model, options);
  try {
    saltus::require_finite(evaluation.samples, "m1.motion.json", "trajectory.csv");
  } catch (const saltus::InputError&) {
    std::abort();
  }
  return 0;
}
