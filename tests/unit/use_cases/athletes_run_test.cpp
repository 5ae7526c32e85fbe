// The athletes study as a job (use_cases/athletes_run.h), without running it: the motion's own
// model is the first case and the others follow in the order given, the take-off rule is part of
// what decides the results, a case whose process failed is recorded with the athlete's size,
// and bad athletes are refused naming the flag or the model before anything runs.

#include "saltus/use_cases/athletes_run.h"

#include <gtest/gtest.h>

#include "saltus/base/input_error.h"
#include "saltus/use_cases/athlete_models.h"
#include "saltus/use_cases/study_kinds.h"
#include "support/cli_runner.h"
#include "support/temp_path.h"

namespace saltus {
namespace {

std::string junior_model() {
  static const std::string path = [] {
    const std::string p = test::temp_path("athletes-run-junior.model.json").string();
    AthleteSize size;
    size.height_m = 1.45;
    size.mass_kg = 38.0;
    size.sex = Sex::kFemale;
    size.name = "junior";
    write_athlete_model(p, new_athlete_model(size));
    return p;
  }();
  return path;
}

TEST(AthletesRun, TheOwnModelComesFirstAndTheRuleDecidesTheResults) {
  const StudyJob job =
      athletes_study_job(test::m1_path(), {junior_model()}, "same-spin", OptimizeOptions{});
  EXPECT_EQ(job.study, kAthletesStudy);
  EXPECT_EQ(&study_kind(job.study).name, &study_kind(kAthletesStudy).name);
  ASSERT_EQ(job.case_names.size(), 2u);
  EXPECT_EQ(job.case_names[0], "M1 on zatsiorsky-66kg");
  EXPECT_EQ(job.case_names[1], "M1 on junior");
  const nlohmann::json& athletes = job.definition["athletes"];
  ASSERT_EQ(athletes.size(), 2u);
  EXPECT_EQ(athletes[1]["name"], "junior");

  const StudyJob keep =
      athletes_study_job(test::m1_path(), {junior_model()}, "keep-momentum", OptimizeOptions{});
  EXPECT_EQ(keep.definition["athletes"][0], athletes[0]);  // the own model keeps its take-off
  EXPECT_NE(keep.definition["athletes"][1]["digest"], athletes[1]["digest"]);
  EXPECT_NE(keep.definition["takeoff"], job.definition["takeoff"]);

  WorkerExit exit;
  exit.kind = WorkerExit::Kind::kTimedOut;
  exit.seconds = 900.0;
  const CaseRecord record = job.unfinished_case(1, exit);
  EXPECT_EQ(record.kind, CaseKind::kAthlete);
  EXPECT_FALSE(record.finished());
  EXPECT_EQ(record.athlete.status, "timed_out");
  EXPECT_EQ(record.athlete.athlete, "junior");
  EXPECT_NEAR(record.athlete.mass_kg, 38.0, 1e-9);
  EXPECT_NEAR(record.athlete.height_m, 1.45, 1e-9);
  EXPECT_EQ(record.athlete.takeoff, "same spin");
}

TEST(AthletesRun, BadAthletesAreRefusedBeforeAnythingRuns) {
  try {
    athletes_study_job(test::m1_path(), {junior_model(), junior_model()}, "same-spin",
                       OptimizeOptions{});
    FAIL() << "two athletes of one name were taken";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--models"), std::string::npos) << e.what();
  }
  EXPECT_THROW(
      athletes_study_job(test::m1_path(), {"zatsiorsky-66kg"}, "same-spin", OptimizeOptions{}),
      InputError);
  EXPECT_THROW(
      athletes_study_job(test::m1_path(), {"no-such-model"}, "same-spin", OptimizeOptions{}),
      InputError);
  EXPECT_THROW(athletes_study_job(test::m1_path(), {junior_model()}, "same", OptimizeOptions{}),
               InputError);
}

}  // namespace
}  // namespace saltus
