// libFuzzer target: a motion file's text, read against the bundled model and exported as
// `saltus export --format bvh` exports it (the default frame rate). Bad input must end in
// InputError (exit 2); an accepted motion must give a valid clip whose BVH text, as Saltus
// writes it, the BVH reader reads back unchanged. Anything else (another exception, a crash, a
// sanitizer report, more than the limits' time or memory) is a finding.

#include <cstdint>
#include <cstdlib>
#include <string>

#include "fuzz_support.h"
#include "saltus/base/input_error.h"
#include "saltus/base/json_reader.h"
#include "saltus/formats/bvh_file.h"
#include "saltus/formats/model_file.h"
#include "saltus/formats/motion_file.h"
#include "saltus/use_cases/captures.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > saltus::kMaxJsonFileBytes) return 0;
  const std::string text(reinterpret_cast<const char*>(data), size);
  saltus::MotionFile source;
  source.path = "fuzz.motion.json";
  source.model = saltus::fuzz::bundled_model();
  saltus::MocapClip clip;
  try {
    source.motion =
        saltus::parse_motion(saltus::parse_json_text(text, source.path), source.path, source.model);
    clip = saltus::export_motion_clip(source, saltus::default_export_fps(source.motion));
  } catch (const saltus::InputError&) {
    return 0;
  }
  // bvh_text throws if the clip is not valid; the file Saltus writes must read back as it is.
  saltus::MocapClip back;
  try {
    back = saltus::parse_bvh(saltus::bvh_text(clip), "exported.bvh");
  } catch (const saltus::InputError&) {
    std::abort();  // Saltus wrote a BVH file its own reader refuses
  }
  saltus::fuzz::abort_unless_same_clip(back, clip);
  return 0;
}
