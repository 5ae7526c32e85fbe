// libFuzzer target: a motion file's text, read against the bundled model as `saltus evaluate`
// reads it. Bad input must end in InputError (exit 2); accepted input must evaluate to finite
// numbers. Anything else (another exception, a crash, a sanitizer report) is a finding.

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "fuzz_support.h"
#include "saltus/base/json_reader.h"
#include "saltus/evaluation/evaluate.h"
#include "saltus/formats/finite_check.h"
#include "saltus/formats/model_file.h"
#include "saltus/formats/motion_file.h"
#include "saltus/use_cases/result_folders.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > saltus::kMaxJsonFileBytes) return 0;
  const std::string text(reinterpret_cast<const char*>(data), size);
  const std::string file = "fuzz.motion.json";
  saltus::Motion motion;
  try {
    motion = saltus::parse_motion(saltus::parse_json_text(text, file), file,
                                  saltus::fuzz::bundled_model());
  } catch (const saltus::InputError&) {
    return 0;
  }
  saltus::EvaluateOptions options;
  options.samples = 9;
  const saltus::MotionEvaluation evaluation =
      saltus::evaluate_motion(motion, saltus::fuzz::bundled_model(), options);
  try {
    // What write_evaluation_outputs checks before it writes (exit 2 naming the field).
    saltus::require_finite(evaluation.samples, file, "trajectory.csv");
  } catch (const saltus::InputError&) {
    std::abort();  // the readers accepted input whose evaluation is not finite
  }
  return 0;
}
