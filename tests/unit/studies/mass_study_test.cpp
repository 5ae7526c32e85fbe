// The mass study (studies/mass_study.h) in a few iterations: the second run's model is the given
// one with the chosen segments' masses and inertias scaled (checked segment by segment), each run
// optimises its own model, and bad segment names or factors are refused before any solve.

#include "saltus/studies/mass_study.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "support/test_motions.h"

namespace saltus {
namespace {

MotionFile tuck_file() {
  MotionFile file;
  file.model = test::bundled_model();
  file.motion = test::tuck_motion(file.model);
  return file;
}

MassStudyOptions quick() {
  MassStudyOptions options;
  options.optimize.nlp.samples = 21;
  options.optimize.solver.max_iterations = 2;
  options.paper_protocol = true;  // knots at the keyframes: the quickest solve
  return options;
}

TEST(MassStudy, RunsTheGivenModelThenTheScaledOne) {
  const MotionFile file = tuck_file();
  const MassStudyResult study = run_mass_study(file, quick());
  ASSERT_EQ(study.runs.size(), 2u);
  EXPECT_EQ(study.runs[0].label, file.model.name);
  EXPECT_EQ(study.runs[1].label, "thigh_l+thigh_r x1.5");
  EXPECT_EQ(study.load_segments, quick().load_segments);
  const BodyModel& given = study.runs[0].model;
  const BodyModel& scaled = study.runs[1].model;
  double added = 0.0;
  for (int i = 0; i < given.size(); ++i) {
    const std::string& name = given.segments[i].name;
    const double factor = name == "thigh_l" || name == "thigh_r" ? 1.5 : 1.0;
    EXPECT_DOUBLE_EQ(scaled.segments[i].mass, factor * file.model.segments[i].mass) << name;
    EXPECT_TRUE(scaled.segments[i].inertia.isApprox(factor * file.model.segments[i].inertia))
        << name;
    EXPECT_EQ(scaled.segments[i].com, file.model.segments[i].com) << name;
    added += (factor - 1.0) * file.model.segments[i].mass;
  }
  EXPECT_NEAR(scaled.total_mass(), file.model.total_mass() + added, 1e-12);
  // Each run starts from the interpolation evaluated with its own model.
  EvaluateOptions grid;
  grid.samples = 21;
  for (const MassStudyRun& run : study.runs) {
    grid.interpolation.knots_per_interval = run.result.knots_per_interval;
    const MotionEvaluation expected = evaluate_motion(file.motion, run.model, grid);
    EXPECT_EQ(run.result.before.metrics.objective, expected.metrics.objective) << run.label;
    EXPECT_EQ(run.result.after.samples.size(), 21u);
  }
  EXPECT_NE(study.runs[0].result.before.metrics.objective,
            study.runs[1].result.before.metrics.objective);
}

TEST(MassStudy, RefusesUnknownSegmentsAndNonPositiveFactors) {
  const MotionFile file = tuck_file();
  MassStudyOptions options = quick();
  options.scaled_segments = {"tail"};
  EXPECT_THROW(run_mass_study(file, options), std::invalid_argument);
  options = quick();
  options.load_segments = {"wing"};
  EXPECT_THROW(run_mass_study(file, options), std::invalid_argument);
  options = quick();
  options.factor = 0.0;
  EXPECT_THROW(run_mass_study(file, options), std::invalid_argument);
}

}  // namespace
}  // namespace saltus
