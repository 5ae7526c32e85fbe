#include "saltus/use_cases/athletes_run.h"

#include <memory>

#include "saltus/base/input_error.h"
#include "saltus/body/mass_properties.h"
#include "saltus/formats/athletes_files.h"
#include "saltus/formats/motion_file.h"
#include "saltus/formats/study_folder.h"
#include "saltus/studies/athlete_study.h"
#include "saltus/use_cases/athlete_models.h"

namespace saltus {

namespace {

CaseRecord athlete_case_record(int index, const std::string& motion, const AthleteOutcome& outcome,
                               const std::string& failure) {
  CaseRecord r;
  r.index = index;
  r.name = motion + " on " + outcome.athlete;
  r.kind = CaseKind::kAthlete;
  r.role = "athlete";
  r.motion = motion;
  r.failure = failure;
  r.athlete = outcome;
  return r;
}

}  // namespace

StudyJob athletes_study_job(const std::string& motion_path, const std::vector<std::string>& models,
                            const std::string& takeoff, const OptimizeOptions& options) {
  const TakeoffRule rule = parse_takeoff_rule(takeoff, "--takeoff");
  const std::string label = motion_label(motion_path);
  auto athletes = std::make_shared<std::vector<MotionFile>>();
  athletes->push_back(load_motion_for_athlete(motion_path, "", rule));
  for (const std::string& model : models) {
    MotionFile athlete = load_motion_for_athlete(motion_path, model, rule);
    for (const MotionFile& earlier : *athletes)
      if (earlier.model.name == athlete.model.name)
        throw InputError("--models", "",
                         "two athletes are named \"" + athlete.model.name + "\" (" + model +
                             (&earlier == &athletes->front() ? ", the motion's own model" : "") +
                             "): give each model once, under a name of its own");
    athletes->push_back(std::move(athlete));
  }

  std::vector<AthleteEntry> entries;
  for (const MotionFile& a : *athletes)
    entries.push_back({a.model.name, motion_digest(a)});
  StudyJob job;
  job.study = kAthletesStudy;
  job.definition = athletes_definition(label, athletes->front(), takeoff, entries, options);
  for (const MotionFile& a : *athletes)
    job.case_names.push_back(label + " on " + a.model.name);
  job.run_case = [athletes, label, options](int index, const std::string&) {
    return athlete_case_record(index, label, run_athlete_case((*athletes)[index], options), "");
  };
  job.unfinished_case = [athletes, label](int index, const WorkerExit& exit) {
    const MotionFile& a = (*athletes)[index];
    AthleteOutcome o;
    o.athlete = a.model.name;
    o.takeoff = a.takeoff_adaptation ? a.takeoff_adaptation->rule : "own model";
    o.mass_kg = a.model.total_mass();
    o.height_m = standing_body(a.model).height();
    o.status = exit.kind == WorkerExit::Kind::kTimedOut ? "timed_out" : "crashed";
    o.seconds = exit.seconds;
    return athlete_case_record(index, label, o, exit.describe());
  };
  return job;
}

nlohmann::json write_athletes_study_outputs(const OutputFolder& folder,
                                            const nlohmann::json& definition,
                                            const std::vector<CaseRecord>& records) {
  return write_athletes_files(folder.file(""), records, definition);
}

}  // namespace saltus
