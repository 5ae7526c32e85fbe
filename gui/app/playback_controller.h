#pragma once
/// @file
/// Playback: the timeline under the 3D view and the Playback menu (play / pause on Space, a frame
/// back or forward on Left / Right, start / end on Home / End, slower / faster on Down / Up,
/// loop). The keys act only in the 3D view, the timeline and the plots (AppContext's shortcut
/// scope), never inside an input field. Keeps the timeline in step with the workspace: a new
/// motion starts at 0, an edit or another run keeps the time.

#include <QObject>

#include "app/app_context.h"

class QAction;
class QMenu;

namespace saltus::gui {

class TimelineWidget;

class PlaybackController : public QObject, public RemembersSettings {
  Q_OBJECT

 public:
  PlaybackController(AppContext& context, TimelineWidget* timeline, QObject* parent = nullptr);

  void fill_menu(QMenu* playback);
  TimelineWidget* timeline() const { return timeline_; }

  /// Pauses and moves to t (clamped to the flight).
  void seek(double t);
  double time() const;
  bool playing() const;

  void load_settings(const QSettings& settings) override;
  void save_settings(QSettings& settings) const override;

 signals:
  /// The time moved (seek, step, playback); `playing` while the clock runs.
  void time_changed(double t, bool playing);

 private:
  void on_workspace(WorkspaceChange change);
  void change_speed(int direction);

  AppContext& context_;
  TimelineWidget* timeline_;
  QAction* play_ = nullptr;
  QAction* loop_ = nullptr;
  std::vector<QAction*> actions_;
};

}  // namespace saltus::gui
