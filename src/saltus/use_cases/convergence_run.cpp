#include "saltus/use_cases/convergence_run.h"

#include <algorithm>
#include <memory>

#include "saltus/base/input_error.h"
#include "saltus/formats/convergence_files.h"

namespace saltus {

namespace {

StudyOutcome unfinished_study_outcome(const StudyCase& study_case, const WorkerExit& exit) {
  return unfinished_outcome(
      study_case, exit.kind == WorkerExit::Kind::kTimedOut ? "timed_out" : "crashed", exit.seconds);
}

}  // namespace

CaseRecord convergence_case_record(int index, const StudyOutcome& outcome,
                                   const std::string& failure) {
  CaseRecord r;
  r.index = index;
  r.name = study_case_label(outcome.study_case);
  r.kind = CaseKind::kConvergence;
  r.role = "convergence";
  r.motion = outcome.study_case.motion;
  r.failure = failure;
  r.convergence = outcome;
  return r;
}

StudyJob convergence_study_job(const std::vector<LabelledMotion>& motions,
                               const ConvergenceStudyOptions& options) {
  for (const std::string& segment : options.mass_segments)
    for (const LabelledMotion& m : motions)
      if (segment != "all" && m.file.model.segment_index(segment) < 0)
        throw InputError(
            m.file.path, "",
            "--mass-segments: model " + m.file.model.name + " has no segment '" + segment + "'");
  auto shared_motions = std::make_shared<const std::vector<LabelledMotion>>(motions);
  auto cases =
      std::make_shared<const std::vector<StudyCase>>(convergence_study_cases(motions, options));
  StudyJob job;
  job.study = kConvergenceStudy;
  job.definition = convergence_definition(motions, options);
  for (const StudyCase& c : *cases)
    job.case_names.push_back(study_case_label(c));
  job.run_case = [shared_motions, cases, options](int index, const std::string&) {
    const StudyCase& c = (*cases)[index];
    const auto motion = std::find_if(shared_motions->begin(), shared_motions->end(),
                                     [&](const LabelledMotion& m) { return m.label == c.motion; });
    return convergence_case_record(index, run_study_case(*motion, c, options), "");
  };
  job.unfinished_case = [cases](int index, const WorkerExit& exit) {
    return convergence_case_record(index, unfinished_study_outcome((*cases)[index], exit),
                                   exit.describe());
  };
  return job;
}

nlohmann::json write_convergence_study_outputs(const OutputFolder& folder,
                                               const nlohmann::json& definition,
                                               const std::vector<CaseRecord>& records) {
  std::vector<StudyOutcome> outcomes;
  for (const CaseRecord& r : records) {
    if (r.kind != CaseKind::kConvergence)
      throw InputError(case_record_name(r.index), "/kind", "not a case of a convergence study");
    outcomes.push_back(r.convergence);
  }
  return write_convergence_files(folder.file(""), outcomes, definition);
}

}  // namespace saltus
