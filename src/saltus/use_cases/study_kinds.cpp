#include "saltus/use_cases/study_kinds.h"

#include "saltus/base/input_error.h"
#include "saltus/formats/athletes_files.h"
#include "saltus/formats/convergence_files.h"
#include "saltus/formats/paper_report_files.h"
#include "saltus/use_cases/athletes_run.h"
#include "saltus/use_cases/convergence_run.h"
#include "saltus/use_cases/paper_report_run.h"

namespace saltus {

const std::vector<StudyKind>& study_kinds() {
  static const std::vector<StudyKind> kinds = {
      {kConvergenceStudy, convergence_folder_kind, write_convergence_study_outputs},
      {kPaperReportStudy, paper_report_folder_kind, write_paper_report_outputs},
      {kAthletesStudy, athletes_folder_kind, write_athletes_study_outputs},
  };
  return kinds;
}

const StudyKind& study_kind(const std::string& name, const std::string& file) {
  for (const StudyKind& kind : study_kinds())
    if (kind.name == name) return kind;
  std::string known;
  for (const StudyKind& kind : study_kinds())
    known += (known.empty() ? "" : ", ") + kind.name;
  throw InputError(file, "/study", "unknown study \"" + name + "\" (known: " + known + ")");
}

}  // namespace saltus
