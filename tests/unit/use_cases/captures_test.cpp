// Captures in and out (use_cases/captures.h): a motion exported as BVH and imported again
// gives back its joint rotations frame by frame (Saltus's own skeleton keeps its heading), the
// import's folder holds the five files and its motion files load; the capture on another model
// (every mass and inertia 1.5 times: the root force of the same kinematics 1.5 times); which
// paths are captures, the export's default rate, and a folder with nothing to export; a capture's
// text imports as its file does, also at 1 ms per frame, and is refused as its file is; an
// export's frame count is the BVH reader's limit at most.

#include "saltus/use_cases/captures.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "saltus/base/input_error.h"
#include "saltus/capture/model_clip.h"
#include "saltus/formats/bvh_file.h"
#include "saltus/formats/motion_file.h"
#include "saltus/formats/plausible_ranges.h"
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

TEST(CaptureFiles, TheTextImportsAsTheFileDoes) {
  MotionFile source;
  source.model = test::bundled_model();
  source.motion = test::tuck_motion(source.model);
  const fs::path bvh = test::temp_path("tuck-text.bvh");
  const MocapClip written = export_motion_bvh(source, bvh.string(), 30.0);
  const CaptureFile from_file = import_capture_file(bvh.string());
  const CaptureFile from_text =
      import_capture_text(bvh_text(written), bvh.string(), test::bundled_model());
  EXPECT_EQ(from_text.model_reference, kDefaultCaptureModel);
  EXPECT_EQ(captured_motion_json(from_text, "model.json"),
            captured_motion_json(from_file, "model.json"));
  EXPECT_EQ(keyframes_motion_json(from_text, "model.json"),
            keyframes_motion_json(from_file, "model.json"));
  try {
    import_capture_text("HIERARCHY\nROOT hips\n", "bad.bvh", test::bundled_model());
    FAIL() << "a truncated capture";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "bad.bvh");
  }
}

TEST(CaptureFiles, TheTextIsRefusedAsTheFileIs) {
  // The text and the file share every check after reading: a capture problem names the part of
  // the input at fault (the BVH file's MOTION line, --flight), and a flight of more frames than
  // import fits is refused before it is fitted.
  MotionFile source;
  source.model = test::bundled_model();
  source.motion = test::tuck_motion(source.model);
  const MocapClip clip = export_motion_clip(source, 1000.0);
  const auto refusal = [&](const MocapClip& bad, const CaptureFileOptions& options) {
    const fs::path bvh = test::temp_path("refused.bvh");
    const std::string text = bvh_text(bad);
    {
      std::ofstream out(bvh);
      out << text;
    }
    std::string from_file, from_text;
    try {
      import_capture_file(bvh.string(), options);
    } catch (const InputError& e) {
      from_file = e.what();
    }
    try {
      import_capture_text(text, bvh.string(), source.model, options);
    } catch (const InputError& e) {
      from_text = e.what();
    }
    EXPECT_EQ(from_text, from_file);
    return from_text;
  };

  MocapClip two = clip;
  two.frames.resize(2);
  const std::string text = bvh_text(two);
  const int motion_line =
      1 + static_cast<int>(std::count(text.begin(), text.begin() + text.find("MOTION"), '\n'));
  EXPECT_NE(refusal(two, {}).find(": line " + std::to_string(motion_line) + ": a clip of fewer"),
            std::string::npos);

  MocapClip many = clip;
  many.frames.resize(plausible::kMaxCaptureFlightFrames + 1, clip.frames.back());
  many.frame_time = 0.001;
  CaptureFileOptions whole;  // every frame, 0-2.5 s
  whole.import.flight = std::make_pair(0.0, 3.0);
  const std::string too_many = refusal(many, whole);
  EXPECT_EQ(too_many.rfind("--flight: ", 0), 0u) << too_many;
  EXPECT_NE(too_many.find("imports at most " + std::to_string(plausible::kMaxCaptureFlightFrames)),
            std::string::npos)
      << too_many;
}

TEST(CaptureFiles, ACaptureAtTheShortestFrameTimeImports) {
  // 1 ms per frame, the shortest accepted: the keyframes are k·0.001 s, and 10·0.001 − 9·0.001
  // falls short of 0.001 by a rounding (the motion reader refused the import's own motion).
  MotionFile source;
  source.model = test::bundled_model();
  source.motion = test::tuck_motion(source.model);
  MocapClip clip = export_motion_clip(source, 1000.0);
  clip.frames.resize(41);
  clip.frame_time = 0.001;
  const CaptureFile capture = import_capture_text(bvh_text(clip), "khz.bvh", source.model);
  ASSERT_EQ(capture.import.captured.keyframes.size(), 41u);
  EXPECT_EQ(capture.import.captured.keyframes[10].time, 10 * 0.001);
}

TEST(CaptureFiles, AnExportHasNoMoreFramesThanTheBvhReaderTakes) {
  MotionFile source;
  source.model = test::bundled_model();
  source.motion = test::tuck_motion(source.model);
  const double flight_time = source.motion.flight_time();
  const MocapClip clip = export_motion_clip(source, 30.0);
  EXPECT_EQ(clip.frame_count(), motion_clip_frame_count(flight_time, 30.0));
  // T·fps = kMaxBvhFrames − 0.4: kMaxBvhFrames + 1 frames once rounded (a floored count let
  // them through, into a file the reader refuses).
  const double fps = (kMaxBvhFrames - 0.4) / flight_time;
  ASSERT_EQ(motion_clip_frame_count(flight_time, fps), kMaxBvhFrames + 1.0);
  EXPECT_THROW(export_motion_clip(source, fps), InputError);
  EXPECT_THROW(export_motion_clip(source, 0.0), InputError);
  EXPECT_THROW(export_motion_clip(source, std::nan("")), InputError);
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

TEST(CaptureFiles, ImportOptionsFromTheFlagsText) {
  const CaptureFileOptions defaults = capture_import_options("m", "map.json", "", "", std::nullopt);
  EXPECT_EQ(defaults.model, "m");
  EXPECT_EQ(defaults.mapping, "map.json");
  EXPECT_FALSE(defaults.import.all_keyframes);
  EXPECT_FALSE(defaults.import.flight.has_value());
  EXPECT_EQ(defaults.import.frame_time, CaptureImportOptions{}.frame_time);
  EXPECT_TRUE(capture_import_options("", "", "all", "", std::nullopt).import.all_keyframes);
  const CaptureFileOptions given = capture_import_options("", "", "7", "0.25:1.5", 0.01);
  EXPECT_EQ(given.import.keyframe_count, 7);
  ASSERT_TRUE(given.import.flight.has_value());
  EXPECT_EQ(given.import.flight->first, 0.25);
  EXPECT_EQ(given.import.flight->second, 1.5);
  EXPECT_EQ(given.import.frame_time, 0.01);
  const auto refused_flag = [](const std::string& keyframes, const std::string& flight,
                               std::optional<double> frame_time) {
    try {
      capture_import_options("", "", keyframes, flight, frame_time);
    } catch (const InputError& e) {
      return e.file();
    }
    return std::string("accepted");
  };
  EXPECT_EQ(refused_flag("1", "", std::nullopt), "--keyframes");
  EXPECT_EQ(refused_flag("2.5", "", std::nullopt), "--keyframes");
  EXPECT_EQ(refused_flag("some", "", std::nullopt), "--keyframes");
  EXPECT_EQ(refused_flag("", "0.5", std::nullopt), "--flight");
  EXPECT_EQ(refused_flag("", "1:0.5", std::nullopt), "--flight");
  EXPECT_EQ(refused_flag("", "a:1", std::nullopt), "--flight");
  EXPECT_EQ(refused_flag("", "", -0.01), "--frame-time");
  EXPECT_EQ(refused_flag("", "", std::nan("")), "--frame-time");
  // 0 was once "the file's"; the capture's range [1 ms, 1 s] holds at the flag, edges included.
  EXPECT_EQ(refused_flag("", "", 0.0), "--frame-time");
  EXPECT_EQ(refused_flag("", "", 0.000999), "--frame-time");
  EXPECT_EQ(refused_flag("", "", 1.0000001), "--frame-time");
  EXPECT_EQ(refused_flag("", "", 0.001), "accepted");
  EXPECT_EQ(refused_flag("", "", 1.0), "accepted");
}

}  // namespace
}  // namespace saltus
