// The list of readable formats: dialog filters, pattern matching, and what a dropped path is
// recognised as (files written by the library's own writers, and look-alikes that are not).

#include "saltus/formats/readable_formats.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "saltus/evaluation/evaluate.h"
#include "saltus/formats/model_file.h"
#include "saltus/formats/motion_file.h"
#include "saltus/formats/result_json.h"
#include "saltus/use_cases/result_folders.h"
#include "support/temp_path.h"

namespace saltus {
namespace {

namespace fs = std::filesystem;

TEST(ReadableFormats, DialogFiltersComeFromTheEntries) {
  EXPECT_EQ(dialog_filter(ReadableKind::kMotion), "Motions (*.motion.json *.json)");
  EXPECT_EQ(save_dialog_filter(ReadableKind::kMotion), "Motions (*.motion.json)");
  EXPECT_EQ(dialog_filter(ReadableKind::kModel), "Body models (*.json)");
  EXPECT_EQ(dialog_filter(ReadableKind::kCapture), "Motion captures (*.bvh *.BVH)");
  for (const ReadableFormat& f : readable_formats()) {
    EXPECT_EQ(&readable_format(f.kind), &f);
    EXPECT_EQ(f.folder, f.patterns.empty()) << f.name;
    EXPECT_TRUE(f.recognises) << f.name;
  }
}

TEST(ReadableFormats, PatternsMatchLikeFileDialogs) {
  EXPECT_TRUE(matches_pattern("M1.motion.json", "*.motion.json"));
  EXPECT_TRUE(matches_pattern("m1.MOTION.JSON", "*.motion.json"));
  EXPECT_TRUE(matches_pattern(".motion.json", "*.motion.json"));
  EXPECT_TRUE(matches_pattern("a.motion.json.motion.json", "*.motion.json"));
  EXPECT_FALSE(matches_pattern("M1.motion.json.bak", "*.motion.json"));
  EXPECT_FALSE(matches_pattern("M1.json", "*.motion.json"));
  EXPECT_TRUE(matches_pattern("M1.json", "*.json"));
  EXPECT_TRUE(matches_pattern("x", "*"));
  EXPECT_FALSE(matches_pattern("capture.bvh", "*.json"));
  EXPECT_TRUE(matches_pattern("a-b-c", "a*c"));
  EXPECT_FALSE(matches_pattern("a-b-d", "a*c"));
}

TEST(ReadableFormats, PathsAreRecognisedByNameAndContent) {
  const fs::path dir = test::temp_path("saltus_readable_formats_test");
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string m1 =
      std::string(SALTUS_EXAMPLES_DIR) + "/motions/M1-straight-back-somersault.motion.json";
  const MotionFile file = load_motion_file(m1);
  EXPECT_EQ(identify_readable(m1), ReadableKind::kMotion);
  // A model saved under any .json name is a model, by its tag.
  std::ofstream((dir / "thighs.json").string()) << body_model_to_json(file.model).dump();
  EXPECT_EQ(identify_readable((dir / "thighs.json").string()), ReadableKind::kModel);
  EXPECT_EQ(identify_readable((dir / "THIGHS.JSON").string()), std::nullopt);  // no such file
  // A result folder, recognised by its result.json's tag; not a file to open as a motion.
  EvaluateOptions options;
  options.samples = 5;
  write_evaluation_outputs((dir / "eval").string(), file,
                           evaluate_motion(file.motion, file.model, options), options);
  EXPECT_EQ(identify_readable((dir / "eval").string()), ReadableKind::kResultFolder);
  EXPECT_EQ(identify_readable((dir / "eval/model.json").string()), ReadableKind::kModel);
  EXPECT_EQ(identify_readable(dir.string()), std::nullopt);
  // Anything else: a text file, a folder with a broken result.json.
  std::ofstream((dir / "notes.txt").string()) << "hello";
  EXPECT_EQ(identify_readable((dir / "notes.txt").string()), std::nullopt);
  fs::create_directories(dir / "broken");
  std::ofstream((dir / "broken/result.json").string()) << "{ not json";
  EXPECT_EQ(identify_readable((dir / "broken").string()), std::nullopt);
  // A capture, by its extension (the BVH reader says what is wrong inside).
  std::ofstream((dir / "jump.BVH").string()) << "HIERARCHY";
  EXPECT_EQ(identify_readable((dir / "jump.BVH").string()), ReadableKind::kCapture);
  // Any other .json is offered as a motion, so the motion reader can say what is wrong with it.
  std::ofstream((dir / "other.json").string()) << "{\"format\": \"something/1\"}";
  EXPECT_EQ(identify_readable((dir / "other.json").string()), ReadableKind::kMotion);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace saltus
