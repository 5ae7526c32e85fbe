// BVH text: what real files contain is read, what would change the motion is an error naming the
// line, and what is written reads back exactly.

#include "saltus/formats/bvh_file.h"

#include <gtest/gtest.h>

#include <sys/stat.h>

#include <chrono>
#include <filesystem>
#include <fstream>

#include "saltus/base/input_error.h"
#include "support/cli_runner.h"
#include "support/input_errors.h"

namespace saltus {
namespace {

// CRLF line endings, tabs, a joint name with a space, an End Site, upper-case channel names as
// MotionBuilder writes them and lower-case ones as some exporters do.
const std::string kText =
    "HIERARCHY\r\n"
    "ROOT Hips\r\n"
    "{\r\n"
    "\tOFFSET 0 90 0\r\n"
    "\tCHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\r\n"
    "\tJOINT Left Up Leg\r\n"
    "\t{\r\n"
    "\t\tOFFSET 8.5 0 0\r\n"
    "\t\tCHANNELS 3 xrotation yrotation zrotation\r\n"
    "\t\tEnd Site\r\n"
    "\t\t{\r\n"
    "\t\t\tOFFSET 0 -42 0\r\n"
    "\t\t}\r\n"
    "\t}\r\n"
    "}\r\n"
    "MOTION\r\n"
    "Frames:\t2\r\n"
    "Frame Time:\t0.0083333\r\n"
    "1 90 2 0 0 0 10 20 30\r\n"
    "1.5 91 2 -5e-1 1e+1 0 0 0 0\r\n";

TEST(BvhFile, ReadsWhatRealFilesContain) {
  const MocapClip clip = parse_bvh(kText, "t.bvh");
  ASSERT_EQ(clip.joint_count(), 2);
  EXPECT_EQ(clip.joints[1].name, "Left Up Leg");
  EXPECT_EQ(clip.joints[1].parent, 0);
  EXPECT_EQ(clip.joints[1].first_column, 6);
  ASSERT_EQ(clip.joints[1].end_sites.size(), 1u);
  EXPECT_EQ(clip.joints[1].end_sites[0], Eigen::Vector3d(0, -42, 0));
  EXPECT_EQ(clip.joints[1].channels[0], MocapChannel::kXrotation);
  EXPECT_EQ(clip.frame_count(), 2);
  EXPECT_DOUBLE_EQ(clip.frame_time, 0.0083333);
  EXPECT_DOUBLE_EQ(clip.frames[1][3], -0.5);
  EXPECT_DOUBLE_EQ(clip.frames[1][4], 10.0);
}

TEST(BvhFile, ReadsFramesWrappedOverLines) {
  std::string text = kText;
  const std::string frame = "1 90 2 0 0 0 10 20 30\r\n";
  text.replace(text.find(frame), frame.size(), "1 90 2 0 0\r\n0 10 20 30\r\n");
  const MocapClip clip = parse_bvh(text, "t.bvh");
  EXPECT_EQ(clip.frames[0], (std::vector<double>{1, 90, 2, 0, 0, 0, 10, 20, 30}));
}

/// The InputError message for `text`, or "" if it parsed.
std::string error_of(const std::string& text) {
  try {
    parse_bvh(text, "bad.bvh");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  text.replace(text.find(from), from.size(), to);
  return text;
}

TEST(BvhFile, ErrorsNameTheFileAndLine) {
  EXPECT_EQ(error_of(replaced(kText, "yrotation", "wrotation")),
            "bad.bvh: line 9: joint \"Left Up Leg\": unknown channel \"wrotation\" (expected "
            "Xposition, Yposition, Zposition, Xrotation, Yrotation or Zrotation)");
  EXPECT_EQ(error_of(replaced(kText, "1.5 91 2 -5e-1 1e+1 0 0 0 0", "1.5 91 2 -5e-1 1e+1 0 0 0")),
            "bad.bvh: line 20: frame 1 has 8 values, expected 9 (one per channel)");
  EXPECT_EQ(error_of(replaced(kText, "1.5 91 2", "1.5 abc 2")),
            "bad.bvh: line 20: expected a number (frame 1 value 2), found \"abc\"");
  EXPECT_EQ(error_of(replaced(kText, "Frames:\t2", "Frames:\t3")),
            "bad.bvh: line 21: the file ends after 2 frames; \"Frames: 3\" announces 3");
  EXPECT_EQ(error_of(replaced(kText, "Frame Time:\t0.0083333", "Frame Time:\t-1")),
            "bad.bvh: line 18: Frame Time: the frame time must be > 0 s, found -1");
  EXPECT_EQ(error_of(replaced(kText, "OFFSET 8.5 0 0", "OFFSET 8.5 0")),
            "bad.bvh: line 9: expected a number (OFFSET of joint \"Left Up Leg\"), found "
            "\"CHANNELS\"");
  EXPECT_EQ(error_of(replaced(kText, "MOTION", "MOTIONS")),
            "bad.bvh: line 16: expected MOTION, found \"MOTIONS\"");
  EXPECT_EQ(error_of(replaced(kText, "Left Up Leg", "Hips")),
            "bad.bvh: line 6: joint name \"Hips\" is used twice");
  EXPECT_EQ(error_of(replaced(kText, "1 90 2 0 0 0 10 20 30", "1 90 2 0 0 0 10 20 30 4")),
            "bad.bvh: line 19: frame 0 has 10 values, expected 9 (one per channel)");
  EXPECT_EQ(error_of(""), "bad.bvh: line 1: the file ends where HIERARCHY was expected");
}

/// A chain of `depth` joints, each nested in the one before, with one frame of zeros.
std::string nested_bvh(int depth) {
  std::string text = "HIERARCHY\nROOT j0\n{\nOFFSET 0 0 0\nCHANNELS 0\n";
  for (int j = 1; j < depth; ++j)
    text += "JOINT j" + std::to_string(j) + "\n{\nOFFSET 0 1 0\nCHANNELS 0\n";
  for (int j = 0; j < depth; ++j)
    text += "}\n";
  return text + "MOTION\nFrames: 1\nFrame Time: 0.01\n\n";
}

TEST(BvhFile, DeepHierarchiesAreReadWithoutRecursionUpToTheLimit) {
  // Issue 28: 12,000 nested joints (0.5 MB) overflowed the stack of the recursive parser.
  const std::string deep = nested_bvh(12000);
  EXPECT_GT(deep.size(), 400000u);
  EXPECT_EQ(error_of(deep), "bad.bvh: line " + std::to_string(2 + 4 * kMaxBvhDepth) +
                                ": the hierarchy is deeper than " + std::to_string(kMaxBvhDepth) +
                                " joints, the most Saltus reads (a human skeleton nests a few "
                                "dozen)");
  const MocapClip at_limit = parse_bvh(nested_bvh(kMaxBvhDepth), "deep.bvh");
  ASSERT_EQ(at_limit.joint_count(), kMaxBvhDepth);
  EXPECT_EQ(at_limit.joints.back().parent, kMaxBvhDepth - 2);
  // Many joints side by side: the joint limit.
  std::string wide = "HIERARCHY\nROOT r\n{\nOFFSET 0 0 0\nCHANNELS 0\n";
  for (int j = 1; j <= kMaxBvhJoints; ++j)
    wide += "JOINT j" + std::to_string(j) + "\n{\nOFFSET 0 1 0\nCHANNELS 0\n}\n";
  EXPECT_EQ(error_of(wide + "}\n")
                .find("bad.bvh: line " + std::to_string(6 + 5 * 999) +
                      ": more than 1000 joints, the most Saltus reads"),
            0u)
      << error_of(wide);
}

TEST(BvhFile, FrameAndChannelCountsAreBoundedBeforeTheDataIsRead) {
  // Issue 28: "Frames: 1000000" ended in bad_alloc; a high count with few data lines is refused
  // at the count, at once.
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(error_of(replaced(kText, "Frames:\t2", "Frames:\t1000000")),
            "bad.bvh: line 17: Frames: 1000000 frames; Saltus reads at most 100000 (14 minutes at "
            "120 Hz; cut the clip around the flight)");
  EXPECT_EQ(
      error_of(replaced(replaced(kText, "CHANNELS 3 xrotation yrotation zrotation", "CHANNELS 0"),
                        "Frames:\t2", "Frames:\t100000000")),
      "bad.bvh: line 17: Frames: 100000000 frames; Saltus reads at most 100000 (14 minutes "
      "at 120 Hz; cut the clip around the flight)");
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 1);
  // 167 joints of 6 channels: 1002 channels.
  std::string many =
      "HIERARCHY\nROOT r\n{\nOFFSET 0 0 0\nCHANNELS 6 Xposition Yposition "
      "Zposition Xrotation Yrotation Zrotation\n";
  for (int j = 1; j < 167; ++j)
    many += "JOINT j" + std::to_string(j) +
            "\n{\nOFFSET 0 1 0\nCHANNELS 6 Xposition Yposition Zposition Xrotation Yrotation "
            "Zrotation\n}\n";
  EXPECT_EQ(error_of(many), "bad.bvh: line " + std::to_string(5 + 5 * 166 - 1) +
                                ": joint \"j166\": more than 1000 channels in the skeleton, the "
                                "most Saltus reads (a human skeleton has a few hundred at most)");
}

TEST(BvhFile, UserTextInMessagesStaysOnOneLine) {
  // A joint name with an ESC sequence, a channel with a control character, a 5000-byte token.
  const std::string escaped = error_of(
      replaced(replaced(kText, "Left Up Leg", "Leg\x1B[2J"), "yrotation", "w\x07rotation"));
  EXPECT_EQ(escaped,
            "bad.bvh: line 9: joint \"Leg\\x1B[2J\": unknown channel \"w\\x07rotation\" "
            "(expected Xposition, Yposition, Zposition, Xrotation, Yrotation or Zrotation)");
  const std::string long_token(5000, 'Q');
  EXPECT_EQ(
      error_of(replaced(kText, "MOTION", long_token)),
      "bad.bvh: line 16: expected MOTION, found \"" + std::string(80, 'Q') + "... (5000 bytes)\"");
}

TEST(BvhFile, FilesThatAreNotRegularOrTooLargeAreRefusedUnread) {
  // Issue 28: a .bvh symlink to /dev/zero grew to 10 GB, a FIFO named x.bvh blocked for ever.
  const auto start = std::chrono::steady_clock::now();
  const test::TempDir dir;
  const std::string fifo = dir / "x.bvh";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_EQ(test::input_error([&] { load_bvh_file(fifo); }),
            fifo +
                ": is not a regular file (a device, pipe or socket); Saltus reads BVH "
                "captures only");
  std::filesystem::create_symlink("/dev/zero", dir / "zero.bvh");
  EXPECT_NE(test::input_error([&] { load_bvh_file(dir / "zero.bvh"); }).find("not a regular file"),
            std::string::npos);
  const std::string big = dir / "big.bvh";
  test::write_text(big, kText);
  std::filesystem::resize_file(big, kMaxBvhFileBytes + 1);  // sparse
  EXPECT_NE(test::input_error([&] { load_bvh_file(big); }).find("at most 64 MiB"),
            std::string::npos);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5);
}

TEST(BvhFile, WrittenTextReadsBackExactly) {
  MocapClip clip = parse_bvh(kText, "t.bvh");
  clip.frames[1][5] = 1.0 / 3.0;  // needs all 17 digits
  clip.joints[1].offset.x() = -2.0 / 7.0;
  const MocapClip back = parse_bvh(bvh_text(clip), "written.bvh");
  ASSERT_EQ(back.joint_count(), clip.joint_count());
  for (int j = 0; j < clip.joint_count(); ++j) {
    EXPECT_EQ(back.joints[j].name, clip.joints[j].name);
    EXPECT_EQ(back.joints[j].parent, clip.joints[j].parent);
    EXPECT_EQ(back.joints[j].offset, clip.joints[j].offset);
    EXPECT_EQ(back.joints[j].channels, clip.joints[j].channels);
    EXPECT_EQ(back.joints[j].end_sites, clip.joints[j].end_sites);
  }
  EXPECT_EQ(back.frames, clip.frames);
  EXPECT_EQ(back.frame_time, clip.frame_time);
}

TEST(BvhFile, SavesAtomically) {
  const test::TempDir dir;
  const std::string path = dir / "out.bvh";
  save_bvh_file(path, parse_bvh(kText, "t.bvh"));
  EXPECT_EQ(load_bvh_file(path).frames, parse_bvh(kText, "t.bvh").frames);
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir.path()))
    files += entry.is_regular_file();
  EXPECT_EQ(files, 1);  // no temporary left behind
  EXPECT_THROW(load_bvh_file(dir / "missing.bvh"), InputError);
}

}  // namespace
}  // namespace saltus
