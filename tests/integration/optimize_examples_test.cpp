// The relaxed model must solve on every bundled motion (examples/motions/*.motion.json) with the
// default settings — the paper's central claim, that moving Newton's laws into the objective makes
// the optimisation converge whatever the skill — with the keyframes within tolerance:
//  - at the paper's resolution (K = 1) the average root force must beat the paper's Table 1
//    value for the same skill;
//  - refined (--knots-per-interval 3) it must fall at least 10× below the interpolation and to
//    1 N or less. At K = 1 a tucked double somersault cannot be followed closely by a spline
//    with knots at 8 keyframes, so the tenfold cut is asked of the refined spline.

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>
#include <vector>

#include "saltus/evaluation/evaluate.h"
#include "saltus/evaluation/joint_loads.h"
#include "saltus/evaluation/simulate.h"
#include "saltus/formats/motion_file.h"
#include "saltus/formats/paper_report_files.h"
#include "saltus/motion/motion.h"
#include "saltus/optim/optimize.h"
#include "saltus/studies/convergence_study.h"
#include "saltus/studies/paper_table1.h"

namespace saltus {
namespace {

std::vector<std::string> bundled_motions() {
  std::vector<std::string> paths;
  for (const auto& entry :
       std::filesystem::directory_iterator(std::string(SALTUS_EXAMPLES_DIR) + "/motions")) {
    const std::string name = entry.path().filename().string();
    if (name.size() > 12 && name.substr(name.size() - 12) == ".motion.json")
      paths.push_back(entry.path().string());
  }
  std::sort(paths.begin(), paths.end());
  return paths;
}

class BundledMotion : public ::testing::TestWithParam<std::string> {};

TEST_P(BundledMotion, RelaxedModelSolvesBeatsThePaperAndRefinesBelowOneNewton) {
  const MotionFile file = load_motion_file(GetParam());
  const std::string label = motion_label(GetParam());
  for (const int knots_per_interval : {1, 3}) {
    OptimizeOptions options;
    options.nlp.knots_per_interval = knots_per_interval;
    const OptimizationResult r = optimize_motion(file.motion, file.model, options);
    const double before = r.before.metrics.avg_root_force;
    const double after = r.after.metrics.avg_root_force;
    std::printf(
        "%s, K = %d: %s after %d iterations, %.2f s; %d variables, %d constraints; "
        "avg root force %.3f -> %.3f N\n",
        file.motion.name.c_str(), knots_per_interval, r.solve.status.c_str(), r.solve.iterations,
        r.solve.seconds, r.variables, r.constraints, before, after);
    EXPECT_TRUE(r.solve.solved) << r.solve.status << ", K = " << knots_per_interval;
    EXPECT_LE(r.after.keyframe_errors.max_quaternion_error, file.motion.tolerances.quaternion);
    EXPECT_LE(r.after.keyframe_errors.max_translation_error_m,
              file.motion.tolerances.translation_m);
    if (knots_per_interval == 1) {
      EXPECT_LT(after, before);
      if (const PaperTableRow* paper = paper_table1(label)) {
        EXPECT_LT(after, paper->force_after) << label << " against the paper's Table 1";
      }
    } else {
      EXPECT_LT(after, before / 10);
      EXPECT_LE(after, 1.0);
    }
  }
}

/// Test name from the file name: "M1-straight-back-somersault" -> "M1_straight_back_somersault".
std::string optimize_test_name(const ::testing::TestParamInfo<std::string>& param) {
  std::string name = std::filesystem::path(param.param).stem().stem().string();
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

INSTANTIATE_TEST_SUITE_P(Examples, BundledMotion, ::testing::ValuesIn(bundled_motions()),
                         optimize_test_name);

/// The bundled dive needs a later step of the polish's ladder: its first two bounded tries land
/// 3-6 deg off. Each bounded step after one that solved starts from that try, within the same
/// bounds, rather than from the levels' optimum, whose joints pay: the third step then ends at
/// 0.391 N (0.452 N when it started from the levels; 13.3 -> 7.2 s). What is returned is a later
/// bounded step, holds at most 0.42 N on a dense grid of its own, keeps every joint within 1.5x
/// and lands within 3 deg by a free flight run here.
TEST(BundledDive, ALaterBoundedStepStartsFromTheTryBeforeIt) {
  const MotionFile file =
      load_motion_file(std::string(SALTUS_EXAMPLES_DIR) +
                       "/motions/dive-5m-front-one-and-a-half-twists.motion.json");
  const OptimizationResult r = optimize_motion(file.motion, file.model, OptimizeOptions{});
  ASSERT_TRUE(r.solve.solved) << r.solve.status;
  ASSERT_TRUE(r.joint_load_polish);
  const JointLoadPolish& polish = *r.joint_load_polish;
  EXPECT_TRUE(polish.kept);
  EXPECT_EQ(polish.joint_bound, kPolishJointBound);
  EXPECT_GE(polish.attempts, 2) << "a later step of the ladder";
  EXPECT_LE(r.after.check.metrics.avg_root_force, 0.42);
  EvaluateOptions dense;
  dense.samples = 4001;
  const double again =
      evaluate_motion(r.optimized_motion, file.model, dense).check.metrics.avg_root_force;
  EXPECT_NEAR(again, r.after.check.metrics.avg_root_force,
              1e-3 * r.after.check.metrics.avg_root_force);
  EXPECT_LE(largest_joint_load_rise(file.model, r.before.check, r.after.check).ratio(), 1.5);
  EXPECT_LE(simulate_motion(r.optimized_motion, file.model).landing_vs_motion_deg, 3.0);
}

}  // namespace
}  // namespace saltus
