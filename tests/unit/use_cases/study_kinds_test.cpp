// The study kinds (use_cases/study_kinds.h): every kind the runner can be given is registered
// once with a writer, and an unknown kind is refused naming study.json's field and the known
// kinds.

#include "saltus/use_cases/study_kinds.h"

#include <gtest/gtest.h>

#include <set>

#include "saltus/base/input_error.h"
#include "saltus/use_cases/athletes_run.h"
#include "saltus/use_cases/convergence_run.h"
#include "saltus/use_cases/paper_report_run.h"

namespace saltus {
namespace {

TEST(StudyKinds, EveryKindIsRegisteredOnceWithAWriter) {
  std::set<std::string> names;
  for (const StudyKind& kind : study_kinds()) {
    EXPECT_TRUE(names.insert(kind.name).second) << kind.name;
    EXPECT_TRUE(static_cast<bool>(kind.write_outputs)) << kind.name;
    EXPECT_EQ(&study_kind(kind.name), &kind);
  }
  EXPECT_EQ(names, (std::set<std::string>{kConvergenceStudy, kPaperReportStudy, kAthletesStudy}));
}

TEST(StudyKinds, AnUnknownKindIsNamedWithTheKnownOnes) {
  try {
    study_kind("mass", "out/study.json");
    FAIL() << "an unknown kind was found";
  } catch (const InputError& e) {
    EXPECT_EQ(e.json_path(), "/study");
    const std::string what = e.what();
    EXPECT_NE(what.find("out/study.json"), std::string::npos) << what;
    EXPECT_NE(what.find("unknown study \"mass\" (known: convergence, paper, athletes)"),
              std::string::npos)
        << what;
  }
}

}  // namespace
}  // namespace saltus
