#pragma once
/// @file
/// Playback controls: play/pause, step, a scrub slider over the sample frames with keyframe ticks
/// (given times grey, optimised times orange) and flags (the closest pass to the apparatus, red
/// when inside it, green when clear; a dive's entry, blue when vertical, purple when not; named
/// in a small legend beside the strip, their figures in the strip's tooltip), speed 0.1×-2×,
/// loop and the time. Owns the Timeline model and the playback clock; emits time_changed
/// whenever the time moves.

#include <QElapsedTimer>
#include <QTimer>
#include <QWidget>
#include <vector>

#include "core/timeline.h"

class QCheckBox;
class QComboBox;
class QLabel;
class QSlider;
class QToolButton;

namespace saltus::gui {

/// The strip under the slider where keyframe ticks and flags are drawn.
class TickStrip : public QWidget {
  Q_OBJECT

 public:
  TickStrip(QSlider* slider, QWidget* parent = nullptr);
  void set_ticks(std::vector<KeyframeTick> ticks);
  /// Flags drawn as small triangles; their texts, one a line, are the strip's tooltip.
  void set_flags(std::vector<TimelineFlag> flags);
  const std::vector<TimelineFlag>& flags() const { return flags_; }
  QSize sizeHint() const override;

 protected:
  void paintEvent(QPaintEvent* event) override;

 private:
  QSlider* slider_;
  std::vector<KeyframeTick> ticks_;
  std::vector<TimelineFlag> flags_;
};

class TimelineWidget : public QWidget {
  Q_OBJECT

 public:
  explicit TimelineWidget(QWidget* parent = nullptr);

  /// A new motion (or stage): range and frame grid, and keyframe ticks (optimised may be empty).
  void set_motion(double duration, int frame_count, const std::vector<double>& given,
                  const std::vector<double>& optimised);
  /// The flags of the flight shown (apparatus_flags); empty for none.
  void set_flags(std::vector<TimelineFlag> flags);
  const std::vector<TimelineFlag>& flags() const;
  /// The flags' legend as plain text ("▲ closest pass, clear"), empty when it is hidden.
  QString flag_legend() const;
  const Timeline& timeline() const { return timeline_; }
  bool playing() const { return timeline_.playing(); }

 public slots:
  void seek(double t);
  void toggle_play();
  void play();
  void pause();
  void step_forward();
  void step_back();
  void go_to_start();
  void go_to_end();
  void set_speed(double speed);
  void set_loop(bool loop);

 signals:
  void time_changed(double t);
  void playing_changed(bool playing);
  void speed_changed(double speed);
  void loop_changed(bool loop);

 private:
  void tick();
  /// Shows the model's state in the controls without feeding back.
  void sync_controls();
  void emit_time();

  Timeline timeline_;
  QTimer clock_;
  QElapsedTimer wall_;
  bool was_playing_ = false;
  QToolButton* play_button_ = nullptr;
  QToolButton* back_button_ = nullptr;
  QToolButton* forward_button_ = nullptr;
  QSlider* slider_ = nullptr;
  TickStrip* ticks_ = nullptr;
  QComboBox* speed_ = nullptr;
  QCheckBox* loop_ = nullptr;
  QLabel* time_label_ = nullptr;
  QLabel* flag_legend_ = nullptr;
};

}  // namespace saltus::gui
