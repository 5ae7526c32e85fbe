#include "core/workspace.h"

#include <stdexcept>

namespace saltus::gui {

void Workspace::set_stage(Stage stage) {
  const Stage available = shown_ ? stage : Stage::kBefore;
  if (available == stage_) return;
  stage_ = available;
  notify(WorkspaceChange::kStage);
}

void Workspace::open(const std::string& motion_path, const std::string& model_override, int samples,
                     const CaptureFileOptions& capture_options) {
  Document loaded;
  loaded.load(motion_path, model_override, samples, capture_options);
  document_ = std::move(loaded);
  // Another motion's runs start again at run 1 (an edit keeps counting: undo may bring back
  // the runs before it).
  runs_ = RunList();
  shown_.reset();
  stage_ = Stage::kBefore;
  ++generation_;
  motion_version_ = saved_motion_version_ = next_version_++;
  model_version_ = saved_model_version_ = next_version_++;
  notify(WorkspaceChange::kOpened);
}

void Workspace::set_motion(const Motion& motion) {
  document_.set_motion(motion);
  runs_.clear();
  shown_.reset();
  stage_ = Stage::kBefore;
  ++generation_;
  motion_version_ = next_version_++;
  notify(WorkspaceChange::kEdited);
}

void Workspace::set_model(const BodyModel& model) {
  document_.set_model(model);
  runs_.clear();
  shown_.reset();
  stage_ = Stage::kBefore;
  ++generation_;
  model_version_ = next_version_++;
  notify(WorkspaceChange::kEdited);
}

int Workspace::add_run(RunRecord run) {
  const std::optional<int> before = runs_.preferred();
  const int index = runs_.add(std::move(run), document_.file().model);
  const std::optional<int> preferred = runs_.preferred();
  // A new run is shown only when it is now the one to show; the user's own choice of another
  // run stays otherwise.
  if (preferred == index && preferred != before) {
    shown_ = index;
    apply_shown();
    stage_ = Stage::kAfter;
  }
  notify(WorkspaceChange::kRuns);
  return index;
}

void Workspace::show_run(std::optional<int> index) {
  if (index && !runs_.showable(*index)) throw std::out_of_range("no result to show");
  shown_ = index;
  apply_shown();
  stage_ = shown_ ? Stage::kAfter : Stage::kBefore;
  notify(WorkspaceChange::kRuns);
}

void Workspace::apply_shown() {
  if (shown_) {
    const RunRecord& run = runs_.at(*shown_);
    document_.set_optimization(*run.result, run.options);
  } else {
    document_.clear_optimization();
  }
}

Workspace::Snapshot Workspace::snapshot() const {
  if (!loaded()) throw std::logic_error("no motion open");
  Snapshot s;
  s.motion = document_.file().motion;
  s.model = document_.file().model;
  s.runs = runs_;
  s.shown = shown_;
  s.stage = stage_;
  s.motion_version = motion_version_;
  s.model_version = model_version_;
  return s;
}

void Workspace::restore(const Snapshot& s) {
  document_.set_motion_and_model(s.motion, s.model);
  runs_ = s.runs;
  shown_ = s.shown && runs_.showable(*s.shown) ? s.shown : std::nullopt;
  apply_shown();
  stage_ = shown_ ? s.stage : Stage::kBefore;
  ++generation_;
  motion_version_ = s.motion_version;
  model_version_ = s.model_version;
  notify(WorkspaceChange::kEdited);
}

std::string Workspace::unsaved_summary() const {
  std::vector<std::string> parts;
  if (motion_unsaved()) parts.push_back("the keyframes were edited");
  if (model_unsaved()) parts.push_back("the masses were edited");
  const int runs = unsaved_runs();
  if (runs == 1) parts.push_back("1 optimisation run was not saved");
  if (runs > 1) parts.push_back(std::to_string(runs) + " optimisation runs were not saved");
  std::string out;
  for (std::size_t i = 0; i < parts.size(); ++i)
    out += (i ? "; " : "") + parts[i];
  return out;
}

void Workspace::mark_motion_saved() {
  saved_motion_version_ = motion_version_;
  notify(WorkspaceChange::kSaved);
}

void Workspace::mark_model_saved() {
  saved_model_version_ = model_version_;
  notify(WorkspaceChange::kSaved);
}

void Workspace::mark_result_saved() {
  if (shown_) runs_.mark_saved(*shown_);
  notify(WorkspaceChange::kSaved);
}

void Workspace::subscribe(std::function<void(WorkspaceChange)> observer) {
  observers_.push_back(std::move(observer));
}

void Workspace::notify(WorkspaceChange change) {
  for (const auto& observer : observers_)
    observer(change);
}

}  // namespace saltus::gui
