// The mass study (§6.1, Fig. 8) reports joint loads a person can produce: optimised as `optimize`
// does, M2's joints stay within 1.5 times what the interpolated input needs on both models, and
// within 1.5 times what the study's own `--max-iter 0` run (the optimiser's starting point, on
// finer knots) needs, while the root force goes below 0.5 N; at the paper's resolution
// (`--paper-protocol`) the joints pay for the root force with peaks many times the input's, which
// is why it is not the default.

#include <gtest/gtest.h>

#include <string>

#include "saltus/evaluation/joint_loads.h"
#include "saltus/formats/motion_file.h"
#include "saltus/studies/mass_study.h"

namespace saltus {
namespace {

double largest_rise(const MassStudyRun& run) {
  return largest_joint_load_rise(run.model, run.result.before.check, run.result.after.check)
      .ratio();
}

TEST(MassStudyLoads, OptimisedAsOptimizeDoesTheJointsDoNotPayForTheRootForce) {
  const MotionFile file = load_motion_file(std::string(SALTUS_EXAMPLES_DIR) +
                                           "/motions/M2-tucked-back-somersault.motion.json");
  MassStudyOptions options;
  const MassStudyResult study = run_mass_study(file, options);
  MassStudyOptions unoptimised = options;
  unoptimised.optimize.solver.max_iterations = 0;
  const MassStudyResult start = run_mass_study(file, unoptimised);
  options.paper_protocol = true;
  const MassStudyResult paper = run_mass_study(file, options);
  for (std::size_t r = 0; r < 2; ++r) {
    const MassStudyRun& run = study.runs[r];
    const double over_start =
        largest_joint_load_rise(run.model, start.runs[r].result.after.check, run.result.after.check)
            .ratio();
    std::printf(
        "%s: %.3f N, largest joint rise %.2fx (%.2fx over --max-iter 0); paper protocol %.3f N, "
        "%.2fx\n",
        run.label.c_str(), run.result.after.metrics.avg_root_force, largest_rise(run), over_start,
        paper.runs[r].result.after.metrics.avg_root_force, largest_rise(paper.runs[r]));
    EXPECT_TRUE(run.result.solve.solved) << run.label;
    EXPECT_LE(run.result.after.metrics.avg_root_force, 0.5) << run.label;
    // Issue 24's bar, both ways. Measured 1.30x and 1.29x over the input, 1.31x and 1.35x over
    // the starting point (the right hip's moment with heavier thighs: 1.86x when the polish's
    // bounds followed the input alone); 2.48x and 1.74x with the effort term alone.
    EXPECT_LE(largest_rise(run), 1.5) << run.label;
    EXPECT_LE(over_start, 1.5) << run.label;
    EXPECT_GE(largest_rise(paper.runs[r]), 10.0) << run.label;
  }
}

}  // namespace
}  // namespace saltus
