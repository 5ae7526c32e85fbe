// Writing result folders (use_cases/result_folders.h): each verb's folder holds exactly its
// files, the optimised motion in it names the model copy beside it and reloads to the motion
// the optimiser returned, and a non-finite number anywhere writes nothing at all.

#include "saltus/use_cases/result_folders.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <set>

#include "saltus/base/input_error.h"
#include "saltus/formats/output_kind.h"
#include "saltus/formats/result_json.h"
#include "support/cli_runner.h"

namespace saltus {
namespace {

namespace fs = std::filesystem;

std::set<std::string> names_in_folder(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir))
    names.insert(entry.path().filename().string());
  return names;
}

MotionFile m1_file() {
  return load_motion_file(std::string(SALTUS_EXAMPLES_DIR) +
                          "/motions/M1-straight-back-somersault.motion.json");
}

TEST(ResultFolders, EachVerbWritesExactlyItsFiles) {
  const MotionFile file = m1_file();
  EvaluateOptions options;
  options.samples = 21;
  test::TempDir dir;
  write_evaluation_outputs(dir / "e", file, evaluate_motion(file.motion, file.model, options),
                           options);
  EXPECT_EQ(names_in_folder(dir / "e"), (std::set<std::string>{"result.json", "trajectory.csv",
                                                               "model.json", kFolderRecordName}));
  write_simulation_outputs(dir / "s", file, simulate_motion(file.motion, file.model, options),
                           options);
  EXPECT_EQ(names_in_folder(dir / "s"), (std::set<std::string>{"result.json", "trajectory.csv",
                                                               "model.json", kFolderRecordName}));

  const WhatIf prepared(file.motion, file.model, options);
  write_what_if_outputs(dir / "w", file, prepared, prepared.fly(WhatIfChange{}));
  EXPECT_EQ(names_in_folder(dir / "w"),
            (std::set<std::string>{"result.json", "what_if.csv", "trajectory.csv", "model.json",
                                   kFolderRecordName}));

  OptimizeOptions optimize;
  optimize.nlp.samples = 21;
  optimize.solver.max_iterations = 3;
  const OptimizationResult result = optimize_motion(file.motion, file.model, optimize);
  write_optimization_outputs(dir / "o", file, result, optimize);
  EXPECT_EQ(names_in_folder(dir / "o"),
            (std::set<std::string>{"result.json", "trajectory_before.csv", "trajectory_after.csv",
                                   "model.json", "optimized.motion.json", kFolderRecordName}));
  // The optimised motion names the model beside it and reloads to the returned motion.
  const MotionFile back = load_motion_file(dir / "o/optimized.motion.json");
  EXPECT_EQ(back.motion.model, "model.json");
  ASSERT_EQ(back.motion.keyframes.size(), result.optimized_motion.keyframes.size());
  for (std::size_t i = 0; i < back.motion.keyframes.size(); ++i)
    EXPECT_NEAR(back.motion.keyframes[i].time, result.optimized_motion.keyframes[i].time, 1e-12);
  EXPECT_EQ(read_result_folder(dir / "o").result.kind, ResultJson::Kind::kOptimization);
}

TEST(ResultFolders, ANonFiniteNumberWritesNothing) {
  const MotionFile file = m1_file();
  EvaluateOptions options;
  options.samples = 11;
  MotionEvaluation e = evaluate_motion(file.motion, file.model, options);
  e.samples[5].com.x() = std::nan("");
  test::TempDir dir;
  EXPECT_THROW(write_evaluation_outputs(dir / "e", file, e, options), InputError);
  EXPECT_FALSE(fs::exists(dir / "e"));
  EXPECT_TRUE(names_in_folder(dir.path()).empty());
}

}  // namespace
}  // namespace saltus
