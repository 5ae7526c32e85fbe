// The export use case (use_cases/motion_exports.h): every format declared once, an unknown one
// refused naming the known ones; a sampled format's files in memory at round(T·fps) + 1 frames,
// the last at T, bounded in size; a folder export written atomically, replaced when it is
// Saltus's and refused over someone else's folder; flags that do not apply refused.

#include "saltus/use_cases/motion_exports.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "saltus/base/input_error.h"
#include "saltus/formats/bvh_file.h"
#include "saltus/formats/csv_table.h"
#include "saltus/formats/plausible_ranges.h"
#include "support/input_errors.h"
#include "support/temp_path.h"
#include "support/test_motions.h"

namespace saltus {
namespace {

namespace fs = std::filesystem;

MotionFile tuck_file() {
  MotionFile source;
  source.model = test::bundled_model();
  source.motion = test::tuck_motion(source.model);
  return source;
}

TEST(MotionExports, EachFormatIsDeclaredOnce) {
  std::set<std::string> names;
  for (const ExportFormat& f : export_formats()) {
    EXPECT_TRUE(names.insert(f.name).second) << f.name;
    EXPECT_FALSE(f.title.empty());
    EXPECT_EQ(&export_format(f.name), &f);
  }
  for (const char* name : {"bvh", "html", "mujoco"})
    EXPECT_TRUE(names.count(name)) << name;
  const std::string message = test::input_error([] { export_format("fbx"); });
  EXPECT_NE(message.find("--format: unknown format \"fbx\" (known: bvh, html, mujoco"),
            std::string::npos)
      << message;
}

TEST(MotionExports, ASampledFormatHoldsRoundTFpsPlusOneFramesTheLastAtT) {
  const MotionFile source = tuck_file();
  const double duration = source.motion.flight_time();
  const std::vector<ExportFile> files = export_files(source, "mujoco", 30.0, "tuck");
  std::set<std::string> names;
  for (const ExportFile& f : files)
    names.insert(f.name);
  EXPECT_EQ(names, (std::set<std::string>{"model.xml", "trajectory.csv", "result.json"}));
  std::istringstream csv(files[1].contents);
  const CsvTable table = parse_csv_table(csv, "trajectory.csv");
  ASSERT_EQ(table.rows.size(), static_cast<std::size_t>(std::round(duration * 30.0)) + 1);
  EXPECT_EQ(table.rows.front()[0], 0.0);
  EXPECT_EQ(table.rows.back()[0], duration);
  const nlohmann::json result = nlohmann::json::parse(files[2].contents);
  EXPECT_EQ(result["format"], "saltus-export/1");
  EXPECT_EQ(result["export"], "mujoco");
  EXPECT_EQ(result["source"], "tuck");
  EXPECT_EQ(result["frames"], table.rows.size());

  EXPECT_THROW(export_files(source, "html", 30.0, "tuck"), std::invalid_argument);
  const std::string message = test::input_error([&] { export_files(source, "mujoco", 1e6, "t"); });
  EXPECT_EQ(message.rfind("--fps: ", 0), 0u) << message;
  EXPECT_NE(message.find("more than an export holds"), std::string::npos) << message;
}

TEST(MotionExports, AFolderIsReplacedWhenSaltusWroteItNeverOtherwise) {
  const MotionFile source = tuck_file();
  const fs::path out = test::temp_path("tuck-mujoco");
  ExportOptions options;
  options.fps = 20.0;
  const ExportSummary summary = export_motion(source, "mujoco", out.string(), options);
  EXPECT_EQ(summary.format, "mujoco");
  EXPECT_EQ(summary.frames, static_cast<int>(std::round(source.motion.flight_time() * 20)) + 1);
  EXPECT_EQ(summary.files.size(), 3u);
  EXPECT_GT(summary.bytes, 1000u);
  EXPECT_TRUE(fs::is_regular_file(out / "model.xml"));
  EXPECT_NO_THROW(export_motion(source, "mujoco", out.string(), options)) << "its own folder";

  const fs::path mine = test::temp_path("my-notes");
  fs::create_directories(mine);
  std::ofstream(mine / "notes.txt") << "mine";
  const std::string message =
      test::input_error([&] { export_motion(source, "mujoco", mine.string(), options); });
  EXPECT_NE(message.find("notes.txt"), std::string::npos) << message;
  EXPECT_EQ(std::set<fs::path>(fs::directory_iterator(mine), fs::directory_iterator()),
            std::set<fs::path>{mine / "notes.txt"});
}

TEST(MotionExports, FlagsThatDoNotApplyAreRefused) {
  const MotionFile source = tuck_file();
  ExportOptions capture;
  capture.capture = "somewhere";
  EXPECT_NE(test::input_error([&] {
              export_motion(source, "mujoco", test::temp_path("c").string(), capture);
            }).find("--capture"),
            std::string::npos);
  EXPECT_NE(test::input_error([&] {
              export_motion(source, "html", test::temp_path("h.html").string());
            }).find("--format"),
            std::string::npos);
  EXPECT_FALSE(fs::exists(test::temp_path("c")));
}

TEST(MotionExports, ABvhIsWrittenOnlyAtFrameTimesItsReaderTakes) {
  const MotionFile source = tuck_file();
  for (const double fps : {2000.0, std::nan(""), -1.0, 0.0, HUGE_VAL}) {
    SCOPED_TRACE(fps);
    ExportOptions options;
    options.fps = fps;
    const std::string out = test::temp_path("fps.bvh").string();
    EXPECT_NE(test::input_error([&] { export_motion(source, "bvh", out, options); }).find("--fps"),
              std::string::npos);
    EXPECT_FALSE(fs::exists(out));
  }
  // Near the edge and at the default: written, and read back by the reader `import` uses.
  for (const double fps : {999.0, 60.0}) {
    ExportOptions options;
    options.fps = fps;
    const std::string out = test::temp_path("edge" + std::to_string(int(fps)) + ".bvh").string();
    fs::remove(out);
    const ExportSummary s = export_motion(source, "bvh", out, options);
    const MocapClip back = load_bvh_file(out);
    EXPECT_EQ(back.frame_time, s.frame_time);
    EXPECT_GE(back.frame_time, plausible::kMinCaptureFrameTime);
    EXPECT_LE(back.frame_time, plausible::kMaxCaptureFrameTime);
  }
}

}  // namespace
}  // namespace saltus
