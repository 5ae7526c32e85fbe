// libFuzzer target: a Yeadon measurement file's text made into an athlete's model as `saltus
// model yeadon` makes it (yeadon_athlete_model_of_text, Dempster's densities, the file's mass).
// Bad input must end in InputError; an accepted model must give finite inverse dynamics for M1's
// keyframes.

#include <cstdint>
#include <optional>
#include <string>

#include "fuzz_support.h"
#include "saltus/use_cases/athlete_models.h"

namespace {

/// The reader's own limit (a measurement file is at most 1 MiB); the fuzzer's inputs are smaller.
constexpr std::size_t kMaxYeadonFuzzBytes = 1u << 20;

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > kMaxYeadonFuzzBytes) return 0;
  const std::string text(reinterpret_cast<const char*>(data), size);
  saltus::BodyModel model;
  try {
    model =
        saltus::yeadon_athlete_model_of_text(text, "fuzz.txt", "dempster", std::nullopt, "").model;
  } catch (const saltus::InputError&) {
    return 0;
  }
  saltus::fuzz::abort_unless_m1_is_finite_on(model);
  return 0;
}
