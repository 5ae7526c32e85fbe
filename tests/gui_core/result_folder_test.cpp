// Fig. 8 from a `saltus study mass` folder: the folder is written by the library's own writer
// (write_mass_outputs, as `saltus study mass` does), read by the library (mass_files, tested in
// tests/unit/formats/mass_files_test.cpp) and drawn as force and moment panels per segment.

#include <gtest/gtest.h>

#include "core/result_folder.h"
#include "gui_core/test_motion.h"
#include "support/mass_study_fixture.h"

namespace saltus::gui {
namespace {

class MassStudyFolderTest : public saltus::test::MassStudyFolderFixture {
 protected:
  static void SetUpTestSuite() {
    write_folder(test::gui_test_motion_path(), MassStudyOptions(), 21, "saltus_gui_mass_study");
  }
};

TEST_F(MassStudyFolderTest, FigureHasForceAndMomentPanelsPerSegmentWithRunLabels) {
  const MassStudyFolder f = read_mass_study_folder(folder_.string());
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
