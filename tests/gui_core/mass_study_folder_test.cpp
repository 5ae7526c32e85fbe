// Fig. 8 from a `saltus study mass` folder: the folder is written by the library's own writer
// (write_mass_outputs, as `saltus study mass` does), read by the library (mass_files, tested in
// tests/unit/formats/mass_files_test.cpp) and drawn as force and moment panels per segment.

#include <gtest/gtest.h>

#include <filesystem>

#include "core/result_folder.h"
#include "gui_core/test_motion.h"
#include "saltus/evaluation/evaluate.h"
#include "saltus/formats/mass_files.h"
#include "saltus/formats/motion_file.h"
#include "saltus/studies/mass_study.h"

namespace saltus::gui {
namespace {

namespace fs = std::filesystem;

/// A mass study without the optimisations (too slow for a unit test): each run's "after" is the
/// interpolated motion evaluated with that run's model, which is all the writer reads.
class MassStudyFolderTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    file_ = new MotionFile(load_motion_file(test::gui_test_motion_path()));
    options_ = new MassStudyOptions();
    study_ = new MassStudyResult();
    study_->load_segments = options_->load_segments;
    EvaluateOptions evaluate;
    evaluate.samples = 21;
    BodyModel scaled = file_->model;
    for (const std::string& s : options_->scaled_segments)
      scaled = scale_segment_mass(scaled, s, options_->factor);
    for (const BodyModel* model : {&file_->model, &scaled}) {
      MassStudyRun run;
      run.label = model == &scaled ? "thighs x1.5" : "table2";
      run.model = *model;
      run.result.before = run.result.after = evaluate_motion(file_->motion, *model, evaluate);
      run.result.solve.status = "not run";
      study_->runs.push_back(std::move(run));
    }
    folder_ = new fs::path(fs::temp_directory_path() / "saltus_gui_mass_study");
    fs::remove_all(*folder_);
    write_mass_outputs(folder_->string(), *file_, *study_, *options_);
  }
  static void TearDownTestSuite() {
    fs::remove_all(*folder_);
    delete folder_;
    delete study_;
    delete options_;
    delete file_;
  }
  static MotionFile* file_;
  static MassStudyOptions* options_;
  static MassStudyResult* study_;
  static fs::path* folder_;
};
MotionFile* MassStudyFolderTest::file_ = nullptr;
MassStudyOptions* MassStudyFolderTest::options_ = nullptr;
MassStudyResult* MassStudyFolderTest::study_ = nullptr;
fs::path* MassStudyFolderTest::folder_ = nullptr;

TEST_F(MassStudyFolderTest, FigureHasForceAndMomentPanelsPerSegmentWithRunLabels) {
  const MassStudyFolder f = read_mass_study_folder(folder_->string());
  const std::vector<FigureGrid> figures = mass_study_figures({f, f});
  ASSERT_EQ(figures.size(), 2u);
  EXPECT_EQ(figures[0].file_name, "saltus_gui_mass_study_loads.png");
  EXPECT_EQ(figures[1].file_name, "saltus_gui_mass_study-2_loads.png");
  EXPECT_EQ(figures[0].columns, 2);
  ASSERT_EQ(figures[0].panels.size(), 2 * f.loads.load_segments.size());
  const ChartSpec& force = figures[0].panels[0];
  const ChartSpec& moment = figures[0].panels[1];
  EXPECT_NE(force.y_title.find("(N)"), std::string::npos) << force.y_title;
  EXPECT_NE(moment.y_title.find("(N·m)"), std::string::npos) << moment.y_title;
  EXPECT_NE(force.x_title.find("(s)"), std::string::npos);
  EXPECT_NE(force.title.find("thigh_r"), std::string::npos) << force.title;
  ASSERT_EQ(force.lines.size(), 2u);
  EXPECT_EQ(force.lines[0].label, "table2");
  EXPECT_EQ(force.lines[1].label, "thighs x1.5");
  EXPECT_EQ(force.lines[1].y, f.loads.loads[0][1].force_N);
  EXPECT_EQ(moment.lines[0].y, f.loads.loads[0][0].moment_Nm);
  EXPECT_EQ(force.lines[0].x, f.loads.time);
  EXPECT_TRUE(force.legend);
}

}  // namespace
}  // namespace saltus::gui
