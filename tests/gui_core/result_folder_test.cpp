// Fig. 8 from a `saltus study mass` folder: the folder is written by the library's own writer
// (write_mass_outputs, as `saltus study mass` does) and the joint-load series read back are
// checked against the joint wrenches of the evaluations that went in.

#include <gtest/gtest.h>

#include <filesystem>

#include "core/result_folder.h"
#include "gui_core/test_motion.h"
#include "saltus/base/input_error.h"
#include "saltus/evaluation/evaluate.h"
#include "saltus/formats/mass_files.h"
#include "saltus/formats/motion_file.h"
#include "saltus/formats/paper_report_files.h"
#include "saltus/studies/convergence_study.h"
#include "saltus/studies/mass_study.h"
#include "support/temp_path.h"

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
    folder_ = new fs::path(saltus::test::temp_path("saltus_gui_mass_study"));
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

TEST_F(MassStudyFolderTest, IsRecognisedByItsStudyField) {
  EXPECT_TRUE(is_mass_study_folder(folder_->string()));
  EXPECT_FALSE(is_mass_study_folder("/nonexistent/folder"));
  EXPECT_FALSE(is_mass_study_folder(SALTUS_EXAMPLES_DIR));
}

TEST_F(MassStudyFolderTest, SeriesAreTheJointWrenchMagnitudesOfBothRuns) {
  const MassStudyFolder f = read_mass_study_folder(folder_->string());
  EXPECT_EQ(f.name, "saltus_gui_mass_study");
  EXPECT_EQ(f.motion, file_->motion.name);
  EXPECT_EQ(f.run_labels[0], "table2");
  EXPECT_EQ(f.run_labels[1], "thighs x1.5");
  ASSERT_EQ(f.loads.time.size(), 21u);
  ASSERT_EQ(f.loads.segments.size(), options_->load_segments.size());
  for (std::size_t s = 0; s < f.loads.segments.size(); ++s) {
    const SegmentLoadSeries& series = f.loads.segments[s];
    EXPECT_EQ(series.segment, options_->load_segments[s]);
    for (std::size_t r = 0; r < 2; ++r) {
      const MassStudyRun& run = study_->runs[r];
      const int index = run.model.segment_index(series.segment);
      ASSERT_EQ(series.force[r].size(), 21u);
      ASSERT_EQ(series.moment[r].size(), 21u);
      for (std::size_t k = 0; k < 21; ++k) {
        const Vector6d& w = run.result.after.samples[k].joint_wrench.at(index);
        EXPECT_NEAR(series.force[r][k], w.head<3>().norm(), 1e-6 * (1 + w.head<3>().norm()));
        EXPECT_NEAR(series.moment[r][k], w.tail<3>().norm(), 1e-6 * (1 + w.tail<3>().norm()));
      }
    }
  }
  // Heavier thighs need a larger force at the hip: the two curves must differ.
  const SegmentLoadSeries& thigh = f.loads.segments[0];
  ASSERT_EQ(thigh.segment, "thigh_r");
  double diff = 0;
  for (std::size_t k = 0; k < 21; ++k)
    diff = std::max(diff, std::abs(thigh.force[1][k] - thigh.force[0][k]));
  EXPECT_GT(diff, 1.0);
}

TEST_F(MassStudyFolderTest, FigureHasForceAndMomentPanelsPerSegmentWithRunLabels) {
  const MassStudyFolder f = read_mass_study_folder(folder_->string());
  const std::vector<FigureGrid> figures = mass_study_figures({f, f});
  ASSERT_EQ(figures.size(), 2u);
  EXPECT_EQ(figures[0].file_name, "saltus_gui_mass_study_loads.png");
  EXPECT_EQ(figures[1].file_name, "saltus_gui_mass_study-2_loads.png");
  EXPECT_EQ(figures[0].columns, 2);
  ASSERT_EQ(figures[0].panels.size(), 2 * f.loads.segments.size());
  const ChartSpec& force = figures[0].panels[0];
  const ChartSpec& moment = figures[0].panels[1];
  EXPECT_NE(force.y_title.find("(N)"), std::string::npos) << force.y_title;
  EXPECT_NE(moment.y_title.find("(N·m)"), std::string::npos) << moment.y_title;
  EXPECT_NE(force.x_title.find("(s)"), std::string::npos);
  EXPECT_NE(force.title.find("thigh_r"), std::string::npos) << force.title;
  ASSERT_EQ(force.lines.size(), 2u);
  EXPECT_EQ(force.lines[0].label, "table2");
  EXPECT_EQ(force.lines[1].label, "thighs x1.5");
  EXPECT_EQ(force.lines[1].y, f.loads.segments[0].force[1]);
  EXPECT_EQ(moment.lines[0].y, f.loads.segments[0].moment[0]);
  EXPECT_TRUE(force.legend);
}

TEST(MassLoadSeries, MissingColumnsNameTheFileAndColumn) {
  CsvTable table;
  table.columns = {"t", "given.thigh_r.force_N", "given.thigh_r.moment_Nm",
                   "scaled.thigh_r.force_N"};
  table.rows = {{0.0, 1.0, 2.0, 3.0}, {0.1, 4.0, 5.0, 6.0}};
  try {
    mass_load_series(table, {"thigh_r"}, "mass.csv");
    ADD_FAILURE() << "a missing column was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("mass.csv"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("scaled.thigh_r.moment_Nm"), std::string::npos)
        << e.what();
  }
  table.columns.push_back("scaled.thigh_r.moment_Nm");
  table.rows = {{0.0, 1.0, 2.0, 3.0, 7.0}, {0.1, 4.0, 5.0, 6.0, 8.0}};
  const MassLoadSeries s = mass_load_series(table, {"thigh_r"}, "mass.csv");
  EXPECT_EQ(s.time, (std::vector<double>{0.0, 0.1}));
  EXPECT_EQ(s.segments[0].force[0], (std::vector<double>{1.0, 4.0}));
  EXPECT_EQ(s.segments[0].moment[0], (std::vector<double>{2.0, 5.0}));
  EXPECT_EQ(s.segments[0].force[1], (std::vector<double>{3.0, 6.0}));
  EXPECT_EQ(s.segments[0].moment[1], (std::vector<double>{7.0, 8.0}));
}

TEST(MassStudyFolder, RejectsOtherFolders) {
  EXPECT_THROW(read_mass_study_folder("/nonexistent/folder"), InputError);
  EXPECT_THROW(read_mass_study_folder(SALTUS_EXAMPLES_DIR), InputError);
}

}  // namespace
}  // namespace saltus::gui
