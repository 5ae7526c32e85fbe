// libFuzzer target: a BVH capture's text, read as `saltus import` reads it. Bad input must end
// in InputError (exit 2); an accepted clip must be valid and read back unchanged from the text
// Saltus writes for it. Anything else (another exception, a crash, a sanitizer report, more than
// the limits' time or memory) is a finding.

#include <cstdint>
#include <cstdlib>
#include <string>

#include "fuzz_support.h"
#include "saltus/base/input_error.h"
#include "saltus/formats/bvh_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > saltus::kMaxBvhFileBytes) return 0;
  const std::string text(reinterpret_cast<const char*>(data), size);
  saltus::MocapClip clip;
  try {
    clip = saltus::parse_bvh(text, "fuzz.bvh");
  } catch (const saltus::InputError&) {
    return 0;
  }
  // The parser's checks imply the clip's invariants; bvh_text throws if one does not hold.
  const saltus::MocapClip back = saltus::parse_bvh(saltus::bvh_text(clip), "written.bvh");
  saltus::fuzz::abort_unless_same_clip(back, clip);
  return 0;
}
