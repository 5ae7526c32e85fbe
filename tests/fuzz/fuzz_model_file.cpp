// libFuzzer target: a body model file's text. Bad input must end in InputError; an accepted
// model must give finite inverse dynamics for M1's keyframes when they fit its joints.

#include <cstdint>
#include <string>

#include "fuzz_support.h"
#include "saltus/base/json_reader.h"
#include "saltus/formats/model_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > saltus::kMaxJsonFileBytes) return 0;
  const std::string text(reinterpret_cast<const char*>(data), size);
  saltus::BodyModel model;
  try {
    model = saltus::parse_body_model(saltus::parse_json_text(text, "fuzz-model.json"),
                                     "fuzz-model.json");
  } catch (const saltus::InputError&) {
    return 0;
  }
  saltus::fuzz::abort_unless_m1_is_finite_on(model);
  return 0;
}
