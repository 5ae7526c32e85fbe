// libFuzzer target: a body model file's text. Bad input must end in InputError; an accepted
// model must give finite inverse dynamics for M1's keyframes when they fit its joints.

#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <string>

#include "saltus/base/json_reader.h"
#include "saltus/evaluation/evaluate.h"
#include "saltus/formats/finite_check.h"
#include "saltus/formats/model_file.h"
#include "saltus/formats/motion_file.h"

namespace {

const nlohmann::json& m1_document() {
  static const nlohmann::json document = saltus::read_json_file(
      std::string(SALTUS_EXAMPLES_DIR) + "/motions/M1-straight-back-somersault.motion.json");
  return document;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > saltus::kMaxJsonFileBytes) return 0;
  const std::string text(reinterpret_cast<const char*>(data), size);
  saltus::BodyModel model;
  saltus::Motion motion;
  try {
    model = saltus::parse_body_model(saltus::parse_json_text(text, "fuzz-model.json"),
                                     "fuzz-model.json");
    motion = saltus::parse_motion(m1_document(), "m1.motion.json", model);
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
