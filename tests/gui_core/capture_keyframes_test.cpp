// A motion imported from a capture: the document keeps the import, plots the capture's own
// residual with the model in use, and keyframes are picked on the capture's frames (added with
// their captured pose, removed, or picked by the library's rule).

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <random>
#include <set>

#include "core/capture_keyframes.h"
#include "core/document.h"
#include "core/model_edit.h"
#include "core/plot_series.h"
#include "gui_core/test_motion.h"
#include "saltus/base/input_error.h"
#include "saltus/evaluation/force_metrics.h"
#include "saltus/formats/motion_file.h"
#include "support/temp_path.h"

namespace saltus::gui {
namespace {

/// The test motion's interpolation written as a BVH file by the library (an exact capture, in
/// the air from the first frame to the last), once per process.
const std::string& capture_path() {
  static const std::string path = [] {
    const std::string out = saltus::test::temp_path("gui-capture.bvh").string();
    export_motion_bvh(load_motion_file(test::gui_test_motion_path()), out, 30.0);
    return out;
  }();
  return path;
}

class CaptureDocument : public ::testing::Test {
 protected:
  void SetUp() override { document_.load(capture_path()); }
  const CaptureFile& capture() const { return *document_.capture(); }
  int frames() const { return static_cast<int>(capture().import.captured.keyframes.size()); }
  Document document_;
};

TEST_F(CaptureDocument, OpensTheImportsPickedKeyframesAndKeepsTheCapture) {
  ASSERT_NE(document_.capture(), nullptr);
  const CaptureFile independent = import_capture_file(capture_path());
  const Motion& motion = document_.file().motion;
  ASSERT_EQ(motion.keyframes.size(), independent.import.keyframes.keyframes.size());
  for (std::size_t k = 0; k < motion.keyframes.size(); ++k) {
    EXPECT_DOUBLE_EQ(motion.keyframes[k].time, independent.import.keyframes.keyframes[k].time);
    for (std::size_t s = 0; s < motion.keyframes[k].rotations.size(); ++s)
      EXPECT_NEAR(motion.keyframes[k].rotations[s].angularDistance(
                      independent.import.keyframes.keyframes[k].rotations[s]),
                  0.0, 1e-12);
  }
  EXPECT_EQ(capture_frames_in(motion, capture()), independent.import.pick.frames);
  EXPECT_DOUBLE_EQ(document_.capture_duration(), independent.import.captured.flight_time());
  // A motion file has none.
  Document plain;
  plain.load(test::gui_test_motion_path());
  EXPECT_EQ(plain.capture(), nullptr);
  EXPECT_TRUE(plain.capture_plot_samples().empty());
}

TEST_F(CaptureDocument, PlotsTheCapturesOwnResidualAsTheImportMeasuredIt) {
  const std::vector<SampleRecord>& samples = document_.capture_plot_samples();
  ASSERT_EQ(samples.size(),
            static_cast<std::size_t>(plot_samples_for(document_.capture_duration())));
  EXPECT_DOUBLE_EQ(samples.back().time, document_.capture_duration());
  // The import's own dense check of the capture, on its own grid: the same average root force
  // to the difference of two quadratures of one curve.
  const double ours = force_metrics(samples).avg_root_force;
  const double import = capture().import.metrics.avg_root_force;
  EXPECT_NEAR(ours, import, 0.02 * import + 0.05) << ours << " vs " << import;
  // One sample at a time is the same evaluation.
  const SampleRecord mid = document_.capture_sample_at(samples[samples.size() / 2].time);
  EXPECT_NEAR((mid.root_wrench - samples[samples.size() / 2].root_wrench).norm(), 0.0, 1e-9);
  // Clamped to the flight.
  EXPECT_DOUBLE_EQ(document_.capture_sample_at(-1.0).time, 0.0);
  EXPECT_DOUBLE_EQ(document_.capture_sample_at(99.0).time, document_.capture_duration());
}

TEST_F(CaptureDocument, AMassEditChangesTheCapturesResidualAKeyframeEditKeepsIt) {
  const double before = force_metrics(document_.capture_plot_samples()).avg_root_force;
  std::vector<double> factors(static_cast<std::size_t>(document_.file().model.size()), 1.0);
  factors[static_cast<std::size_t>(document_.file().model.segment_index("thigh_l"))] = 2.0;
  document_.set_model(model_with_mass_factors(document_.loaded_model(), factors));
  ASSERT_NE(document_.capture(), nullptr);
  const double heavier = force_metrics(document_.capture_plot_samples()).avg_root_force;
  EXPECT_GT(std::abs(heavier - before), 1e-3 * before);
  const Motion toggled = with_capture_frame_toggled(document_.file().motion, document_.file().model,
                                                    capture(), frames() / 2);
  document_.set_motion(toggled);
  EXPECT_NEAR(force_metrics(document_.capture_plot_samples()).avg_root_force, heavier, 1e-12);
}

TEST_F(CaptureDocument, TogglingFramesAddsTheCapturedPoseOrRemovesIt) {
  // A seeded family of toggle sequences: after each, the keyframes are exactly the expected
  // captured frames, each with the captured rotations and root position.
  const std::vector<Keyframe>& captured = capture().import.captured.keyframes;
  for (unsigned seed = 1; seed <= 5; ++seed) {
    std::mt19937 random(seed);
    std::uniform_int_distribution<int> interior(1, frames() - 2);
    Motion motion = document_.file().motion;
    const std::vector<int> start = capture_frames_in(motion, capture());
    std::set<int> expected(start.begin(), start.end());
    for (int step = 0; step < 8; ++step) {
      const int f = interior(random);
      motion = with_capture_frame_toggled(motion, document_.file().model, capture(), f);
      if (!expected.erase(f)) expected.insert(f);
      const std::vector<int> now = capture_frames_in(motion, capture());
      ASSERT_EQ(std::set<int>(now.begin(), now.end()), expected) << "seed " << seed;
      ASSERT_EQ(motion.keyframes.size(), expected.size());
      std::size_t k = 0;
      for (int frame : expected) {
        const Keyframe& key = motion.keyframes[k++];
        const Keyframe& source = captured[static_cast<std::size_t>(frame)];
        EXPECT_DOUBLE_EQ(key.time, source.time);
        for (std::size_t s = 0; s < key.rotations.size(); ++s)
          EXPECT_NEAR(key.rotations[s].angularDistance(source.rotations[s]), 0.0, 1e-12);
        ASSERT_TRUE(key.root_position && source.root_position);
        EXPECT_NEAR((*key.root_position - *source.root_position).norm(), 0.0, 1e-12);
      }
    }
  }
}

TEST_F(CaptureDocument, TheFlightsEndsStayKeyframes) {
  const Motion& motion = document_.file().motion;
  for (int f : {0, frames() - 1}) {
    ASSERT_TRUE(capture_frame_toggle_problem(motion, capture(), f).has_value());
    EXPECT_THROW(with_capture_frame_toggled(motion, document_.file().model, capture(), f),
                 std::invalid_argument);
  }
  EXPECT_TRUE(capture_frame_toggle_problem(motion, capture(), frames()).has_value());
  EXPECT_TRUE(capture_frame_toggle_problem(motion, capture(), -1).has_value());
  EXPECT_FALSE(capture_frame_toggle_problem(motion, capture(), 1).has_value());
}

TEST_F(CaptureDocument, AutomaticPicksAreTheLibrarys) {
  const std::vector<int> every = automatic_capture_frames(capture(), true);
  ASSERT_EQ(static_cast<int>(every.size()), frames());
  const Motion all =
      with_capture_frames(document_.file().motion, document_.file().model, capture(), every);
  EXPECT_EQ(all.keyframes.size(), every.size());
  EXPECT_EQ(all.name, document_.file().motion.name);
  EXPECT_EQ(all.model, document_.file().motion.model);
  EXPECT_NEAR(capture_pick_errors(capture(), every).max_quaternion_error, 0.0, 1e-12);
  const std::vector<int> picked = automatic_capture_frames(capture(), false);
  EXPECT_EQ(picked, pick_keyframes(capture().import.captured, capture().model).frames);
  // The rule: within the keyframe tolerance of every captured frame.
  EXPECT_LE(capture_pick_errors(capture(), picked).max_quaternion_error,
            capture().import.captured.tolerances.quaternion);
  EXPECT_LT(picked.size(), every.size());
}

TEST_F(CaptureDocument, RootChartsShowTheCaptureBesideTheMotion) {
  const WrenchSeries motion = root_wrench_series(document_.plot_samples(Stage::kBefore));
  const WrenchSeries captured = root_wrench_series(document_.capture_plot_samples());
  RootChartStyle style;
  style.log_scale = true;
  const ChartSpec chart = root_chart(style, motion, nullptr, {}, {}, &captured);
  ASSERT_GE(chart.lines.size(), 2u);
  EXPECT_EQ(chart.lines[0].label, "|F| capture");
  EXPECT_EQ(chart.lines[0].y, captured.force_magnitude);
  EXPECT_EQ(chart.lines[1].label, "|F| keyframes");
  EXPECT_TRUE(chart.log_y);  // the capture's residual is far from the motion's
  style.components = true;
  const ChartSpec components = root_chart(style, motion, nullptr, {}, {}, &captured);
  EXPECT_EQ(components.lines.size(), 6u);
  EXPECT_EQ(components.lines[2].label, "z capture");
  EXPECT_EQ(components.lines[2].y, captured.component[2]);
  // Without a capture, nothing of it.
  for (const LineSpec& line : root_chart(style, motion, nullptr, {}, {}).lines)
    EXPECT_EQ(line.label.find("capture"), std::string::npos);
}

TEST(CaptureImport, ABrokenFileIsAnInputErrorNamingItAndTheDocumentStays) {
  const std::string bad = saltus::test::temp_path("broken.bvh").string();
  {
    std::ofstream out(bad);
    out << "HIERARCHY\nROOT Hips\n{\n  OFFSET 0 0\n";
  }
  Document d;
  d.load(test::gui_test_motion_path());
  try {
    d.load(bad);
    FAIL() << "a broken BVH file loaded";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("broken.bvh"), std::string::npos) << e.what();
  }
  EXPECT_EQ(d.capture(), nullptr);
  EXPECT_EQ(d.file().path, test::gui_test_motion_path());
}

}  // namespace
}  // namespace saltus::gui
