// The one summary every study keeps of an optimisation (studies/run_summary.h): its figures are
// the result's own, the average root force is √(J/6) of the objective it sits beside, and only
// a case whose process died is not completed.

#include "saltus/studies/run_summary.h"

#include <gtest/gtest.h>

#include <cmath>

#include "saltus/formats/motion_file.h"

namespace saltus {
namespace {

TEST(RunSummary, HoldsTheResultsFiguresAndTheirRelations) {
  const MotionFile file = load_motion_file(std::string(SALTUS_EXAMPLES_DIR) +
                                           "/motions/M1-straight-back-somersault.motion.json");
  OptimizeOptions options = paper_protocol_options();
  options.nlp.samples = 21;
  options.solver.max_iterations = 4;
  const OptimizationResult result = optimize_motion(file.motion, file.model, options);
  const RunSummary s = summarize_run(file.motion, result);
  EXPECT_EQ(s.motion_name, file.motion.name);
  EXPECT_EQ(s.keyframes, static_cast<int>(file.motion.keyframes.size()));
  EXPECT_EQ(s.status, result.solve.status);
  EXPECT_EQ(s.iterations, result.solve.iterations);
  EXPECT_EQ(s.variables, result.variables);
  EXPECT_NEAR(s.avg_force_before, std::sqrt(s.objective_before / 6), 1e-9 * s.avg_force_before);
  EXPECT_NEAR(s.avg_force_after, std::sqrt(s.objective_after / 6), 1e-9 * s.avg_force_before);
  EXPECT_LT(s.avg_force_after, s.avg_force_before);
  EXPECT_GE(s.max_force_after, s.avg_force_after);
  EXPECT_EQ(s.keyframe_times_before.size(), file.motion.keyframes.size());
  EXPECT_EQ(s.keyframe_times_after.size(), file.motion.keyframes.size());
  EXPECT_TRUE(s.completed());
  RunSummary died = s;
  for (const char* status : {"crashed", "timed_out"}) {
    died.status = status;
    EXPECT_FALSE(died.completed()) << status;
  }
}

}  // namespace
}  // namespace saltus
