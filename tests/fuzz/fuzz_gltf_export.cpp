// libFuzzer target: a motion file's text, read against the bundled model and exported as
// `saltus export --format gltf` exports it (at kFuzzExportFps). Bad input must end in InputError
// (exit 2); an accepted motion must give one .glb whose container Saltus's reader accepts, whose
// every buffer view lies on a 4-byte boundary inside the buffer, whose every accessor fits its
// view, every float finite, with min and max equal to the stored floats where given, and whose
// animation has one time per frame. Anything else (another exception, a crash, a sanitizer
// report, more than the limits' time or memory) is a finding.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>

#include "fuzz_support.h"
#include "saltus/formats/gltf_file.h"
#include "saltus/use_cases/motion_exports.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::optional<saltus::fuzz::FuzzedExport> exported =
      saltus::fuzz::fuzzed_export(data, size, "gltf");
  if (!exported) return 0;
  const std::vector<saltus::ExportFile>& files = exported->files;
  const std::size_t frames = exported->frames;
  if (files.size() != 1) std::abort();
  const std::string& glb = files[0].contents;
  nlohmann::json json;
  try {
    json = saltus::read_glb_json(glb, "fuzz.glb");
  } catch (const saltus::InputError&) {
    std::abort();  // Saltus wrote a container its own reader refuses
  }
  std::uint32_t json_length;
  std::memcpy(&json_length, glb.data() + 12, 4);
  const std::size_t bin = 20 + json_length + 8;
  const std::size_t bin_length = glb.size() - bin;
  if (json["buffers"][0]["byteLength"] != bin_length) std::abort();
  for (const nlohmann::json& a : json["accessors"]) {
    const nlohmann::json& view = json["bufferViews"][a["bufferView"].get<std::size_t>()];
    const std::size_t offset = view["byteOffset"], length = view["byteLength"];
    if (offset % 4 != 0 || offset + length > bin_length) std::abort();
    const std::string type = a["type"];
    const std::size_t width = type == "SCALAR" ? 1 : type == "VEC3" ? 3 : 4;
    const bool is_float = a["componentType"] == 5126;
    const std::size_t count = a["count"];
    if (count * width * (is_float ? 4 : 2) > length) std::abort();
    if (!is_float) continue;
    for (std::size_t c = 0; c < width; ++c) {
      float low = INFINITY, high = -INFINITY;
      for (std::size_t i = c; i < count * width; i += width) {
        float f;
        std::memcpy(&f, glb.data() + bin + offset + 4 * i, 4);
        if (!std::isfinite(f)) std::abort();
        low = std::min(low, f);
        high = std::max(high, f);
      }
      if (a.contains("min") &&
          (a["min"][c].get<double>() != low || a["max"][c].get<double>() != high))
        std::abort();
    }
  }
  const nlohmann::json& input =
      json["accessors"][json["animations"][0]["samplers"][0]["input"].get<std::size_t>()];
  if (input["count"] != frames) std::abort();
  return 0;
}
