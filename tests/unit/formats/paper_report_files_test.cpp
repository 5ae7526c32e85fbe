// The reproduction report's files (formats/paper_report_files.h) from a report assembled by
// hand: report.md carries our Table 1 row beside the paper's, result.json the same figures, a
// failed run shows as a dash, never as a number. (The whole report:
// tests/paper/paper_report_test.cpp.)

#include "saltus/formats/paper_report_files.h"

#include <gtest/gtest.h>

#include "saltus/formats/convergence_files.h"
#include "saltus/optim/option_table.h"
#include "support/cli_runner.h"

namespace saltus {
namespace {

RunSummary a_run(const std::string& status, double after) {
  RunSummary r;
  r.motion_name = "M1 straight back somersault";
  r.keyframes = 5;
  r.status = status;
  r.solved = status == "solved";
  r.iterations = 31;
  r.seconds = 0.4;
  r.variables = 297;
  r.constraints = 84;
  r.objective_before = 600;
  r.objective_after = 6 * after * after;
  r.avg_force_before = 10;
  r.avg_force_after = after;
  return r;
}

nlohmann::json a_definition() {
  OptimizeOptions optimize;
  use_paper_protocol(optimize);
  return {{"quick", true},
          {"optimize", result_deciding_settings(optimize)},
          {"convergence", convergence_definition({}, ConvergenceStudyOptions{})}};
}

TEST(PaperReportFiles, TheReportAndResultJsonCarryTheSameFigures) {
  test::TempDir dir;
  PaperReport report;
  report.skills.push_back({"M1", a_run("solved", 0.0123), std::nullopt});
  report.skills.push_back({"M2", a_run("crashed", 0.0), std::nullopt});
  report.mass_markdown = "No M7 among the motions.\n";
  OutputFolder folder(dir / "report", paper_report_folder_kind());
  const nlohmann::json result = write_paper_report_files(folder, a_definition(), report, 1);
  folder.commit();
  const std::string md = test::read_text(dir / "report/report.md");
  EXPECT_NE(md.find("| M1 | 5 | 297 | 84 |"), std::string::npos) << md;
  EXPECT_NE(md.find("0.0123"), std::string::npos);
  EXPECT_NE(md.find("| M2 | 5 | – | – |"), std::string::npos) << md;
  EXPECT_NE(md.find("**Quick run**"), std::string::npos);
  ASSERT_EQ(result["table1"].size(), 2u);
  EXPECT_DOUBLE_EQ(result["table1"][0]["avg_force_after_N"].get<double>(), 0.0123);
  EXPECT_TRUE(result["table1"][1]["avg_force_after_N"].is_null());
  EXPECT_EQ(result["failed_cases"], 1);
  EXPECT_EQ(test::read_json(dir / "report/result.json"), result);
}

}  // namespace
}  // namespace saltus
