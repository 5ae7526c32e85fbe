// BVH text: what real files contain is read, what would change the motion is an error naming the
// line, and what is written reads back exactly.

#include "saltus/formats/bvh_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "saltus/base/input_error.h"
#include "support/cli_runner.h"

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
            "bad.bvh: line 18: the frame time must be > 0 s, found -1");
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
