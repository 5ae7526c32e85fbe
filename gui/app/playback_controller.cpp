#include "app/playback_controller.h"

#include <QAction>
#include <QMenu>
#include <QSettings>

#include "app/timeline_widget.h"
#include "saltus/evaluation/apparatus.h"
#include "saltus/evaluation/clearance.h"

namespace saltus::gui {

PlaybackController::PlaybackController(AppContext& context, TimelineWidget* timeline,
                                       QObject* parent)
    : QObject(parent), context_(context), timeline_(timeline) {
  auto add = [this](const QString& text, const QKeySequence& key, auto slot) {
    auto* a = new QAction(text, this);
    a->setShortcut(key);
    connect(a, &QAction::triggered, this, slot);
    context_.scope_shortcut(a);
    actions_.push_back(a);
    return a;
  };
  play_ = add(tr("&Play / pause"), Qt::Key_Space, [this] { timeline_->toggle_play(); });
  add(tr("Step &back"), Qt::Key_Left, [this] { timeline_->step_back(); });
  add(tr("Step &forward"), Qt::Key_Right, [this] { timeline_->step_forward(); });
  add(tr("Go to &start"), Qt::Key_Home, [this] { timeline_->go_to_start(); });
  add(tr("Go to &end"), Qt::Key_End, [this] { timeline_->go_to_end(); });
  add(tr("S&lower"), Qt::Key_Down, [this] { change_speed(-1); });
  add(tr("F&aster"), Qt::Key_Up, [this] { change_speed(+1); });
  loop_ = new QAction(tr("&Loop"), this);
  loop_->setCheckable(true);
  loop_->setChecked(timeline_->timeline().loop());
  connect(loop_, &QAction::toggled, timeline_, &TimelineWidget::set_loop);
  connect(timeline_, &TimelineWidget::loop_changed, loop_, &QAction::setChecked);
  connect(timeline_, &TimelineWidget::playing_changed, this, [this](bool playing) {
    play_->setText(playing ? tr("&Pause") : tr("&Play"));
    // The last frame of a playback is drawn in full (texts included).
    if (!playing) emit time_changed(time(), false);
  });
  connect(timeline_, &TimelineWidget::time_changed, this,
          [this](double t) { emit time_changed(t, timeline_->playing()); });
  context_.workspace().subscribe([this](WorkspaceChange c) { on_workspace(c); });
  on_workspace(WorkspaceChange::kOpened);
}

void PlaybackController::fill_menu(QMenu* playback) {
  for (QAction* a : actions_)
    playback->addAction(a);
  playback->addAction(loop_);
}

void PlaybackController::on_workspace(WorkspaceChange change) {
  const Workspace& ws = context_.workspace();
  if (change == WorkspaceChange::kSaved) return;
  timeline_->setEnabled(ws.loaded());
  for (QAction* a : actions_)
    a->setEnabled(ws.loaded());
  if (!ws.loaded()) return;
  const Document& d = ws.document();
  std::vector<double> optimised;
  if (d.has_optimization()) optimised = d.evaluation(Stage::kAfter).keyframe_times;
  const double t = time();
  timeline_->set_motion(d.duration(), d.frame_count(ws.stage()),
                        d.evaluation(Stage::kBefore).keyframe_times, optimised);
  // The closest pass to the apparatus and a dive's entry, of the stage shown.
  const std::vector<SampleRecord>& samples = d.evaluation(ws.stage()).samples;
  const Apparatus apparatus = apparatus_for(d.file().model, d.file().motion.takeoff, samples);
  timeline_->set_flags(apparatus_flags(apparatus_clearance(d.file().model, apparatus, samples),
                                       dive_entry(d.file().model, apparatus, samples),
                                       d.duration()));
  // A new motion starts at take-off; an edit, a run or another stage keep the moment shown.
  timeline_->seek(change == WorkspaceChange::kOpened ? 0.0 : std::min(t, d.duration()));
}

void PlaybackController::change_speed(int direction) {
  const std::vector<double> choices = speed_choices();
  const double now = timeline_->timeline().speed();
  double next = direction > 0 ? choices.back() : choices.front();
  if (direction > 0) {
    for (auto it = choices.rbegin(); it != choices.rend(); ++it)
      if (*it > now + 1e-9) next = *it;
  } else {
    for (double s : choices)
      if (s < now - 1e-9) next = s;
  }
  timeline_->set_speed(next);
}

void PlaybackController::seek(double t) {
  timeline_->pause();
  timeline_->seek(t);
}

double PlaybackController::time() const {
  return timeline_->timeline().time();
}

bool PlaybackController::playing() const {
  return timeline_->playing();
}

void PlaybackController::load_settings(const QSettings& s) {
  timeline_->set_speed(s.value("playback/speed", 1.0).toDouble());
  timeline_->set_loop(s.value("playback/loop", true).toBool());
}

void PlaybackController::save_settings(QSettings& s) const {
  s.setValue("playback/speed", timeline_->timeline().speed());
  s.setValue("playback/loop", timeline_->timeline().loop());
}

}  // namespace saltus::gui
