// The convergence study as a runner's job (use_cases/convergence_run.h): one named case per
// study case, the study's definition, the record of a case whose process died, and the outputs
// refused for records of another kind.

#include "saltus/use_cases/convergence_run.h"

#include <gtest/gtest.h>

#include "saltus/base/input_error.h"
#include "saltus/formats/convergence_files.h"
#include "support/cli_runner.h"

namespace saltus {
namespace {

LabelledMotion labelled_m1() {
  return {"M1", load_motion_file(std::string(SALTUS_EXAMPLES_DIR) +
                                 "/motions/M1-straight-back-somersault.motion.json")};
}

ConvergenceStudyOptions small_design() {
  ConvergenceStudyOptions o;
  o.epsilons = {50, 500};
  o.mass_errors = {0.0, 0.1};
  o.timing_errors = {0.0};
  return o;
}

TEST(ConvergenceRun, OneNamedCasePerStudyCaseAndTheStudysDefinition) {
  const std::vector<LabelledMotion> motions = {labelled_m1()};
  const StudyJob job = convergence_study_job(motions, small_design());
  const std::vector<StudyCase> cases = convergence_study_cases(motions, small_design());
  ASSERT_EQ(job.case_names.size(), cases.size());
  EXPECT_EQ(cases.size(), 6u);  // (relaxed + 2 strict) x 2 mass errors
  for (std::size_t i = 0; i < cases.size(); ++i)
    EXPECT_EQ(job.case_names[i], study_case_label(cases[i]));
  EXPECT_EQ(job.study, kConvergenceStudy);
  EXPECT_EQ(job.definition, convergence_definition(motions, small_design()));
}

TEST(ConvergenceRun, ACaseWhoseProcessDiedIsRecordedAsSuch) {
  const StudyJob job = convergence_study_job({labelled_m1()}, small_design());
  WorkerExit exit;
  exit.kind = WorkerExit::Kind::kTimedOut;
  exit.seconds = 600;
  const CaseRecord r = job.unfinished_case(2, exit);
  EXPECT_EQ(r.index, 2);
  EXPECT_EQ(r.name, job.case_names[2]);
  EXPECT_FALSE(r.finished());
  EXPECT_EQ(r.failure, exit.describe());
  EXPECT_EQ(r.convergence.status, "timed_out");
  EXPECT_FALSE(r.convergence.solved);
}

TEST(ConvergenceRun, OutputsAreRefusedForRecordsOfAnotherKind) {
  test::TempDir dir;
  CaseRecord other;
  other.kind = CaseKind::kOptimization;
  OutputFolder folder(dir / "c", convergence_folder_kind());
  EXPECT_THROW(
      write_convergence_study_outputs(folder, convergence_definition({}, small_design()), {other}),
      InputError);
}

TEST(ConvergenceRun, AMassSegmentTheModelLacksIsRefusedNamingTheMotion) {
  ConvergenceStudyOptions o = small_design();
  o.mass_segments = {"all", "tail"};
  try {
    convergence_study_job({labelled_m1()}, o);
    FAIL() << "a segment the model lacks was taken";
  } catch (const InputError& e) {
    EXPECT_NE(e.file().find("M1-straight-back-somersault"), std::string::npos) << e.what();
    EXPECT_NE(e.problem().find("--mass-segments"), std::string::npos) << e.what();
    EXPECT_NE(e.problem().find("'tail'"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace saltus
