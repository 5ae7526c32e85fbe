// The result list's rule: every run is kept, ranked as the optimiser ranks its solves (solved,
// then the joints within the joint policy, then the root force); the one shown by default is the
// best, if it solved or improved on the interpolation; a cancelled, failed or worse run never
// replaces a solved one, nor a run whose joints pay one whose joints keep to their loads. Runs
// here are built from evaluations with chosen outcomes, so each case of the rule is tested on
// purpose.

#include <gtest/gtest.h>

#include <memory>

#include "core/run_list.h"
#include "support/test_motions.h"

namespace saltus::gui {
namespace {

const BodyModel& model() {
  static const BodyModel bundled = saltus::test::bundled_model();
  return bundled;
}

int ankle() {
  for (int k = 1; k < model().size(); ++k)
    if (model().segments[k].joint == "ankle_l") return k;
  return 1;
}

/// The list with `runs` added on the bundled model.
void add_all(RunList& list, std::initializer_list<RunRecord> runs) {
  for (const RunRecord& r : runs)
    list.add(r, model());
}

/// A finished run: `status`, average root force `before` -> `after` N; `rise`: the left
/// ankle's peak moment after over before (1: every joint as before).
RunRecord run(const std::string& status, double before, double after, double rise = 1.0) {
  auto result = std::make_shared<OptimizationResult>();
  result->solve.status = status;
  result->solve.solved = status == "solved";
  result->solve.iterations = 12;
  result->before.metrics.avg_root_force = before;
  result->after.metrics.avg_root_force = after;
  JointLoadPeak peak;
  peak.moment_Nm = 30.0;
  result->before.check.joint_peaks.assign(model().size(), peak);
  result->after.check.joint_peaks = result->before.check.joint_peaks;
  result->after.check.joint_peaks[ankle()].moment_Nm = 30.0 * rise;
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
  list.add(run("solved", 90.0, 13.1), model());
  EXPECT_EQ(list.preferred(), 0);
  // The case: a cancelled run at 90 N (worse than before) must not replace 13.1 N.
  list.add(run("cancelled", 90.0, 90.5), model());
  EXPECT_EQ(list.preferred(), 0);
  // Nor a cancelled run that is better: it did not solve.
  list.add(run("cancelled", 90.0, 5.0), model());
  EXPECT_EQ(list.preferred(), 0);
  list.add(failed("out of memory"), model());
  EXPECT_EQ(list.preferred(), 0);
  // A better solved run takes over.
  list.add(run("solved", 90.0, 11.0), model());
  EXPECT_EQ(list.preferred(), 4);
  // A worse solved run does not.
  list.add(run("solved", 90.0, 12.0), model());
  EXPECT_EQ(list.preferred(), 4);
  EXPECT_EQ(list.size(), 6);
  EXPECT_EQ(list.at(5).number, 6);
}

TEST(RunList, WithoutASolvedRunTheBestImprovementIsShownAndNothingWorse) {
  RunList list;
  list.add(run("cancelled", 90.0, 95.0), model());  // worse than the interpolation
  EXPECT_FALSE(list.preferred());
  list.add(run("max_iterations", 90.0, 40.0), model());
  EXPECT_EQ(list.preferred(), 1);
  list.add(run("cancelled", 90.0, 30.0), model());
  EXPECT_EQ(list.preferred(), 2);
  EXPECT_TRUE(list.showable(0));
  list.add(failed("boom"), model());
  EXPECT_FALSE(list.showable(3));
}

TEST(RunList, ACancelledRunOrOneWhoseJointsPayNeverOutranksAFullRunWithinTheJointPolicy) {
  // The case: Run M7, Cancel: "solved" by its first levels at 0.08 N with an ankle at
  // 4.71x (the library now calls it cancelled); Run again: 0.239 N, every joint within 1.27x.
  RunList list;
  add_all(list, {run("cancelled", 169.0, 0.08, 4.71), run("solved", 169.0, 0.239, 1.27)});
  EXPECT_EQ(list.preferred(), 1);
  EXPECT_EQ(list.ranking(), (std::vector<int>{1, 0}));
  // Both solved: the one whose joints keep to their loads, whatever the root force.
  add_all(list, {run("solved", 169.0, 0.05, 4.71)});
  EXPECT_EQ(list.preferred(), 1);
  EXPECT_EQ(list.ranking(), (std::vector<int>{1, 2, 0}));
  // A solved run within the policy and with less root force takes over.
  add_all(list, {run("solved", 169.0, 0.2, 1.1), failed("boom")});
  EXPECT_EQ(list.preferred(), 3);
  EXPECT_EQ(list.ranking(), (std::vector<int>{3, 1, 2, 0, 4}));
  // The list says which is best, that the cancelled run was cancelled and what its joints did,
  // in the words of `saltus optimize`.
  EXPECT_EQ(list.label(3).rfind("Best · Run 4 · solved", 0), 0u) << list.label(3);
  EXPECT_EQ(list.label(1).rfind("Run 2 · solved", 0), 0u) << list.label(1);
  EXPECT_NE(list.label(0).find("cancelled"), std::string::npos) << list.label(0);
  EXPECT_NE(list.label(0).find("ankle_l carries 4.71x its peak load before"), std::string::npos)
      << list.label(0);
  EXPECT_NE(list.label(1).find("every joint within 1.27x of its peak load before"),
            std::string::npos)
      << list.label(1);
  EXPECT_EQ(list.label(1).find("strength"), std::string::npos) << list.label(1);
  // A run whose optimised motion asks two joints for more than the athlete's strength says so.
  RunRecord strained = run("solved", 169.0, 0.239, 1.27);
  auto result = std::make_shared<OptimizationResult>(*strained.result);
  result->after.check.strength_peaks.resize(4);
  for (int k : {1, 2, 3}) {
    result->after.check.strength_peaks[k].coordinate = 0;
    result->after.check.strength_peaks[k].share = k == 1 ? 0.9 : 9.62;
  }
  strained.result = result;
  add_all(list, {strained});
  EXPECT_NE(list.label(5).find(" · 2 joints beyond the athlete's strength"), std::string::npos)
      << list.label(5);
}

TEST(RunList, CountsUnsavedRunsAndLabelsThemInWords) {
  RunList list;
  list.add(run("max_iterations", 118.0, 11.2), model());
  list.add(failed("the solver threw"), model());
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
