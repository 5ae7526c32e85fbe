// libFuzzer target: a skeleton mapping file's text, read and applied to the bundled DeepMimic
// capture as `saltus import --mapping` does up to the retargeting plan. Bad input must end in
// InputError, or in std::invalid_argument from the mapping (import_capture_file turns it into an
// InputError naming the file); anything else (another exception, a crash, a sanitizer report)
// is a finding.

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "fuzz_support.h"
#include "saltus/base/json_reader.h"
#include "saltus/capture/retarget.h"
#include "saltus/capture/skeleton_mapping.h"
#include "saltus/formats/bvh_file.h"
#include "saltus/formats/capture_mapping_file.h"
#include "saltus/formats/model_file.h"

namespace {

const saltus::MocapClip& bundled_clip() {
  static const saltus::MocapClip clip =
      saltus::load_bvh_file(std::string(SALTUS_EXAMPLES_DIR) + "/captures/deepmimic-backflip.bvh");
  return clip;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > saltus::kMaxJsonFileBytes) return 0;
  const std::string text(reinterpret_cast<const char*>(data), size);
  const std::string file = "fuzz.mapping.json";
  try {
    const saltus::SkeletonMapping given =
        saltus::parse_capture_mapping(saltus::parse_json_text(text, file), file);
    saltus::check_capture_mapping(given, bundled_clip(), file, "backflip.bvh");
    const saltus::SkeletonMapping merged = saltus::merge_skeleton_mapping(bundled_clip(), given);
    const saltus::Retargeting plan =
        saltus::plan_retargeting(bundled_clip(), saltus::fuzz::bundled_model(), merged);
    if (!(plan.axes.metres_per_unit > 0) || !std::isfinite(plan.axes.metres_per_unit)) std::abort();
  } catch (const saltus::InputError&) {
    return 0;
  } catch (const std::invalid_argument&) {
    return 0;
  }
  return 0;
}
