// The result list's rule: every run is kept; the one shown by default is the best solved run,
// else the best run that improved on the interpolation; a cancelled, failed or worse run never
// replaces a solved one. Runs here are built from evaluations with chosen outcomes, so each case
// of the rule is tested on purpose.

#include <gtest/gtest.h>

#include <memory>

#include "core/run_list.h"

namespace saltus::gui {
namespace {

/// A finished run: `status`, average root force `before` -> `after` N.
RunRecord run(const std::string& status, double before, double after) {
  auto result = std::make_shared<OptimizationResult>();
  result->solve.status = status;
  result->solve.solved = status == "solved";
  result->solve.iterations = 12;
  result->before.metrics.avg_root_force = before;
  result->after.metrics.avg_root_force = after;
  RunRecord r;
  r.result = result;
  return r;
}

RunRecord failed(const std::string& why) {
  RunRecord r;
  r.error = why;
  return r;
}

TEST(RunList, TheBestSolvedRunIsShownAndACancelledOneNeverReplacesIt) {
  RunList list;
  EXPECT_FALSE(list.preferred());
  list.add(run("solved", 90.0, 13.1));
  EXPECT_EQ(list.preferred(), 0);
  // The case: a cancelled run at 90 N (worse than before) must not replace 13.1 N.
  list.add(run("cancelled", 90.0, 90.5));
  EXPECT_EQ(list.preferred(), 0);
  // Nor a cancelled run that is better: it did not solve.
  list.add(run("cancelled", 90.0, 5.0));
  EXPECT_EQ(list.preferred(), 0);
  list.add(failed("out of memory"));
  EXPECT_EQ(list.preferred(), 0);
  // A better solved run takes over.
  list.add(run("solved", 90.0, 11.0));
  EXPECT_EQ(list.preferred(), 4);
  // A worse solved run does not.
  list.add(run("solved", 90.0, 12.0));
  EXPECT_EQ(list.preferred(), 4);
  EXPECT_EQ(list.size(), 6);
  EXPECT_EQ(list.at(5).number, 6);
}

TEST(RunList, WithoutASolvedRunTheBestImprovementIsShownAndNothingWorse) {
  RunList list;
  list.add(run("cancelled", 90.0, 95.0));  // worse than the interpolation
  EXPECT_FALSE(list.preferred());
  list.add(run("max_iterations", 90.0, 40.0));
  EXPECT_EQ(list.preferred(), 1);
  list.add(run("cancelled", 90.0, 30.0));
  EXPECT_EQ(list.preferred(), 2);
  EXPECT_TRUE(list.showable(0));
  list.add(failed("boom"));
  EXPECT_FALSE(list.showable(3));
}

TEST(RunList, CountsUnsavedRunsAndLabelsThemInWords) {
  RunList list;
  list.add(run("max_iterations", 118.0, 11.2));
  list.add(failed("the solver threw"));
  EXPECT_EQ(list.unsaved(), 1);  // a failed run has nothing to save
  list.mark_saved(0);
  EXPECT_EQ(list.unsaved(), 0);
  const std::string label = list.label(0);
  EXPECT_NE(label.find("Run 1"), std::string::npos) << label;
  EXPECT_NE(label.find("stopped at the iteration limit"), std::string::npos) << label;
  EXPECT_NE(label.find("118 → 11.2 N"), std::string::npos) << label;
  EXPECT_NE(list.label(1).find("failed: the solver threw"), std::string::npos);
  EXPECT_EQ(status_text("solved"), "solved");
  EXPECT_EQ(status_text("some_new_status"), "some_new_status");
}

TEST(RunList, SettingsSummaryNamesWhatARunUsed) {
  OptimizeSettings s;
  EXPECT_EQ(settings_summary(s), "relaxed, times free, knots auto, 101 samples, joint turn ≤ 180°");
  s.set("knots_per_interval", 1);
  EXPECT_EQ(settings_summary(s), "relaxed, times free, K = 1, 101 samples, joint turn ≤ 180°");
  s.set("formulation", std::string("strict"));
  s.set("epsilon", 50.0);
  s.set("optimize_timing", false);
  s.set("max_joint_turn", 0.0);
  EXPECT_EQ(settings_summary(s), "strict, ε = 50, times fixed, K = 1, 101 samples");
}

}  // namespace
}  // namespace saltus::gui
