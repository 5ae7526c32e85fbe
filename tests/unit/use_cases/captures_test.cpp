// Captures in and out (use_cases/captures.h): a motion exported as BVH and imported again
// gives back its joint rotations frame by frame (Saltus's own skeleton keeps its heading), the
// import's folder holds the five files and its motion files load; the capture on another model
// (every mass and inertia 1.5 times: the root force of the same kinematics 1.5 times); which
// paths are captures, the export's default rate, and a folder with nothing to export.

#include "saltus/use_cases/captures.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "saltus/base/input_error.h"
#include "saltus/formats/bvh_file.h"
#include "saltus/formats/motion_file.h"
#include "saltus/math/quaternion.h"
#include "saltus/motion/interpolate.h"
#include "support/temp_path.h"
#include "support/test_motions.h"

namespace saltus {
namespace {

namespace fs = std::filesystem;

TEST(CaptureFiles, ExportThenImportGivesTheMotionBack) {
  MotionFile source;
  source.model = test::bundled_model();
  source.motion = test::tuck_motion(source.model);
  const fs::path bvh = test::temp_path("tuck.bvh");
  const MocapClip written = export_motion_bvh(source, bvh.string(), 30.0);
  EXPECT_EQ(load_bvh_file(bvh.string()).frames, written.frames) << "shortest round-trip text";

  const CaptureFile capture = import_capture_file(bvh.string());
  EXPECT_EQ(capture.path, bvh.string());
  EXPECT_EQ(capture.model.name, source.model.name) << "the default capture model";
  const Motion& captured = capture.import.captured;
  ASSERT_EQ(static_cast<int>(captured.keyframes.size()), written.frame_count())
      << "no ground contact: every frame is flight";
  const Trajectory<double> trajectory = motion_trajectory(source.motion, source.model);
  BodyState<double> state(source.model.size());
  for (const Keyframe& k : captured.keyframes) {
    trajectory.sample(std::min(k.time, trajectory.duration()), state);
    for (int s = 0; s < source.model.size(); ++s)
      EXPECT_LT(rotation_angle_between(k.rotations[s], state.joints[s].q), 1e-9)
          << "t=" << k.time << " segment " << s;
    EXPECT_LT((*k.root_position - state.root_position).norm(), 1e-9) << "t=" << k.time;
  }

  const fs::path folder = test::temp_path("tuck-import");
  write_capture_outputs(folder.string(), capture);
  for (const char* name : {"result.json", "capture.motion.json", "keyframes.motion.json",
                           "trajectory.csv", "model.json"})
    EXPECT_TRUE(fs::is_regular_file(folder / name)) << name;
  const MotionFile reloaded = load_motion_file((folder / "capture.motion.json").string());
  EXPECT_EQ(reloaded.motion.keyframes.size(), captured.keyframes.size());
  EXPECT_EQ(load_export_source(folder.string()).motion.keyframes.size(), captured.keyframes.size());
  EXPECT_EQ(load_motion_or_capture(bvh.string()).motion.keyframes.size(),
            capture.import.keyframes.keyframes.size());
}

TEST(CaptureFiles, OnAHeavierModelTheSameKinematicsNeedMoreRootForce) {
  MotionFile source;
  source.model = test::bundled_model();
  source.motion = test::tuck_motion(source.model);
  const fs::path bvh = test::temp_path("tuck-heavier.bvh");
  export_motion_bvh(source, bvh.string(), 30.0);
  const CaptureFile capture = import_capture_file(bvh.string());

  const CaptureFile same = capture_on_model(capture, capture.model);
  EXPECT_NEAR(same.import.metrics.avg_root_force, capture.import.metrics.avg_root_force,
              1e-9 * capture.import.metrics.avg_root_force);
  // Inverse dynamics is linear in the masses and inertias for given kinematics.
  BodyModel heavier = capture.model;
  for (Segment& segment : heavier.segments) {
    segment.mass *= 1.5;
    segment.inertia *= 1.5;
  }
  const CaptureFile heavy = capture_on_model(capture, heavier);
  ASSERT_EQ(heavy.import.samples.size(), capture.import.samples.size());
  for (std::size_t i = 0; i < heavy.import.samples.size(); ++i)
    EXPECT_EQ(heavy.import.samples[i].time, capture.import.samples[i].time);
  EXPECT_NEAR(heavy.import.metrics.avg_root_force, 1.5 * capture.import.metrics.avg_root_force,
              1e-6 * capture.import.metrics.avg_root_force);
  EXPECT_EQ(heavy.model.total_mass(), heavier.total_mass());

  BodyModel other = capture.model;
  other.segments.pop_back();
  EXPECT_THROW(capture_on_model(capture, other), std::invalid_argument);
}

TEST(CaptureFiles, CapturePathsAndTheDefaultRate) {
  EXPECT_TRUE(is_capture_path("a/b/jump.bvh"));
  EXPECT_TRUE(is_capture_path("JUMP.BVH"));
  EXPECT_FALSE(is_capture_path("jump.motion.json"));
  EXPECT_FALSE(is_capture_path("bvh"));

  Motion motion;
  for (int i = 0; i < 5; ++i)
    motion.keyframes.push_back({i / 25.0, {}, {}});
  EXPECT_NEAR(default_export_fps(motion), 25.0, 1e-9) << "evenly spaced: the frames' own rate";
  motion.keyframes[2].time = 0.09;
  EXPECT_EQ(default_export_fps(motion), 60.0);
  motion.keyframes.resize(2);
  EXPECT_EQ(default_export_fps(motion), 60.0);
}

TEST(CaptureFiles, AFolderWithNothingToExportIsAnInputError) {
  const fs::path empty = test::temp_path("nothing-here");
  fs::create_directories(empty);
  EXPECT_THROW(load_export_source(empty.string()), InputError);
}

}  // namespace
}  // namespace saltus
