#pragma once
// What several fuzz targets share: the bundled model, loaded once, and the check that a BVH
// clip Saltus wrote reads back as it was written.

#include <cstdlib>
#include <string>

#include "saltus/capture/mocap_clip.h"
#include "saltus/formats/model_file.h"

namespace saltus::fuzz {

inline const BodyModel& bundled_model() {
  static const BodyModel model =
      load_body_model(std::string(SALTUS_RESOURCES_DIR) + "/models/zatsiorsky-66kg.json");
  return model;
}

/// Aborts (a finding) unless `back` has `clip`'s frames, frame time and skeleton.
inline void abort_unless_same_clip(const MocapClip& back, const MocapClip& clip) {
  if (back.frames != clip.frames || back.frame_time != clip.frame_time ||
      back.joint_count() != clip.joint_count())
    std::abort();
  for (int j = 0; j < clip.joint_count(); ++j)
    if (back.joints[j].name != clip.joints[j].name ||
        back.joints[j].parent != clip.joints[j].parent ||
        back.joints[j].offset != clip.joints[j].offset ||
        back.joints[j].channels != clip.joints[j].channels ||
        back.joints[j].end_sites != clip.joints[j].end_sites)
      std::abort();
}

}  // namespace saltus::fuzz
