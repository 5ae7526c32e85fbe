// The study progress line (formats/study_progress.h): what the command line prints after every
// case reads back to the same counts, times and case, and nothing else is taken for one (the app
// follows a study through these lines).

#include "saltus/formats/study_progress.h"

#include <gtest/gtest.h>

#include "saltus/formats/study_case_file.h"

namespace saltus {
namespace {

CaseRecord convergence_record() {
  CaseRecord r;
  r.index = 11;
  r.name = "M1 strict ε=10, mass -10 % (thigh_r), timing ±0.05 s";
  r.kind = CaseKind::kConvergence;
  r.convergence.status = "solved";
  r.convergence.iterations = 37;
  r.convergence.avg_force_after = 2.125;
  return r;
}

TEST(StudyProgress, TheLineReadsBackToWhatItSays) {
  const CaseRecord record = convergence_record();
  StudyProgress p;
  p.done = 12;
  p.total = 140;
  p.failed = 1;
  p.unsolved = 3;
  p.elapsed_s = 41.4;
  p.eta_s = 3725.0;
  p.last = &record;
  const std::string line = study_progress_line(p);
  EXPECT_EQ(line,
            "  [ 12/140] 1 failed, 3 not solved, 0:41 elapsed, ETA 1:02:05  M1 strict ε=10, mass "
            "-10 % (thigh_r), timing ±0.05 s: solved, 37 it., 2.12 N");
  const std::optional<StudyProgressLine> read = parse_study_progress_line(line + "\n");
  ASSERT_TRUE(read.has_value());
  EXPECT_EQ(read->done, 12);
  EXPECT_EQ(read->total, 140);
  EXPECT_EQ(read->failed, 1);
  EXPECT_EQ(read->unsolved, 3);
  EXPECT_EQ(read->elapsed_s, 41.0);
  EXPECT_EQ(read->eta_s, 3725.0);
  EXPECT_EQ(read->last_case, record.name);
  EXPECT_EQ(read->last_result, "solved, 37 it., 2.12 N");
}

TEST(StudyProgress, AnUnknownEtaAndAFailedCase) {
  CaseRecord record = convergence_record();
  record.failure = "killed by signal 11 (Segmentation fault)";
  StudyProgress p;
  p.done = 1;
  p.total = 4;
  p.failed = 1;
  p.last = &record;
  const std::optional<StudyProgressLine> read = parse_study_progress_line(study_progress_line(p));
  ASSERT_TRUE(read.has_value());
  EXPECT_EQ(read->eta_s, -1.0);
  EXPECT_EQ(read->failed, 1);
  EXPECT_EQ(read->last_result, record.failure);
}

TEST(StudyProgress, OtherLinesAreNotProgress) {
  for (const std::string line :
       {"saltus: error: m.motion.json: /keyframes/2/time: must increase",
        "saltus study convergence: 4 cases, 2 at a time", "  [3/x] 0 failed", "",
        "  [5/4] 0 failed, 0 not solved, 0:01 elapsed, ETA ?  M1 relaxed: solved, 3 it., 1 N",
        "  [1/4] 0 failed, 0 not solved, soon elapsed, ETA ?  M1 relaxed: solved, 3 it., 1 N"})
    EXPECT_FALSE(parse_study_progress_line(line).has_value()) << line;
}

TEST(StudyProgress, ClockText) {
  EXPECT_EQ(clock_text(0.4), "0:00");
  EXPECT_EQ(clock_text(59.6), "1:00");
  EXPECT_EQ(clock_text(3599.4), "59:59");
  EXPECT_EQ(clock_text(3600.0), "1:00:00");
}

}  // namespace
}  // namespace saltus
