#pragma once
/// @file
/// The What if panel: the same take-off with the tuck moved earlier or later, the opening moved,
/// or the tuck made tighter or looser (three sliders and Reset), flown again by the library's
/// `what_if` while a slider moves: somersaults and twists at landing and how far short or over
/// the landing the motion was keyframed to ("you land 14° over"). It works on a worker thread,
/// one flight at a time, and a newer slider value always wins: each finished flight is shown
/// with the settings it was flown for (its sentence names them), and the newest setting is
/// flown next; a flight for another motion than the one shown is never shown. While in view, the
/// what-if flight is drawn as a second figure beside the athlete (flight_changed()).

#include <QElapsedTimer>
#include <QString>
#include <QWidget>
#include <memory>
#include <optional>
#include <thread>
#include <vector>

#include "app/app_context.h"
#include "core/shown_motion.h"
#include "core/what_if_report.h"

class QLabel;
class QPushButton;
class QSlider;

namespace saltus::gui {

class WhatIfPanel : public QWidget {
  Q_OBJECT

 public:
  explicit WhatIfPanel(AppContext& context, QWidget* parent = nullptr);
  /// Waits for a flight still being worked out (its result is dropped).
  ~WhatIfPanel() override;

  /// In view or not (its dock raised or hidden): flies only in view, and the 3D view shows the
  /// what-if figure only then.
  void set_active(bool active);
  bool active() const { return active_; }

  QSlider* tuck_slider() const { return tuck_; }
  QSlider* open_slider() const { return open_; }
  QSlider* tightness_slider() const { return tightness_; }
  QPushButton* reset_button() const { return reset_; }
  /// Back to the motion as it is (every slider at "as keyframed"), as the Reset button does.
  void reset();

  /// The change the sliders ask for now.
  WhatIfChange change() const;
  /// Whether the answer shown is not yet the one for the motion and the sliders as they are.
  bool busy() const;
  /// What is shown (tests): the sentence (or the message shown instead), which motion it is
  /// about, the tuck the library found, the result shown (none while there is none).
  QString sentence() const;
  QString subject() const;
  QString tuck() const;
  const std::optional<WhatIfResult>& result() const { return shown_; }
  /// The what-if flight the 3D view should draw beside the athlete, null when none is (no
  /// result, or the panel out of view), and its label ("what if: opening 0.05 s later").
  const SimulationResult* flight() const;
  QString flight_label() const;

  /// From a slider's change (or Reset, or another motion) to its answer on screen, ms: the
  /// last one and every one since the motion was opened.
  double last_latency_ms() const { return last_latency_ms_; }
  const std::vector<double>& latencies_ms() const { return latencies_ms_; }
  /// Wall time of the last what-if flight on the worker thread, ms.
  double last_flight_ms() const { return last_flight_ms_; }

 signals:
  /// A result (or the library's message) is on screen.
  void result_shown();
  /// What flight() returns changed: draw it (or none) beside the athlete.
  void flight_changed();

 private:
  struct Request {
    ShownMotion::Key key;
    WhatIfChange change;
  };
  struct Done {
    Request request;
    std::shared_ptr<const WhatIf> prepared;  ///< null: the library refused the motion (`error`)
    std::optional<WhatIfResult> result;      ///< empty: the library refused (`error`)
    QString error;
    double flight_ms = 0.0;
  };

  void refresh();
  void on_slider();
  void request();
  void start();
  void on_finished(Done done);
  void show_result(const WhatIfResult& result);
  void show_message(const QString& text);
  void set_sliders(const TuckPhases* tuck);
  void update_slider_texts();
  bool wanted_now(const Request& request) const;

  AppContext& context_;
  QLabel* subject_ = nullptr;
  QLabel* tuck_text_ = nullptr;
  QSlider* tuck_ = nullptr;
  QSlider* open_ = nullptr;
  QSlider* tightness_ = nullptr;
  QLabel* tuck_value_ = nullptr;
  QLabel* open_value_ = nullptr;
  QLabel* tightness_value_ = nullptr;
  QPushButton* reset_ = nullptr;
  QLabel* sentence_ = nullptr;
  QLabel* reference_ = nullptr;
  QLabel* timing_ = nullptr;

  bool active_ = false;
  std::optional<ShownMotion> subject_now_;  ///< the motion shown; none without one
  std::shared_ptr<const WhatIf> prepared_;  ///< for subject_now_, once worked out
  QString prepare_error_;                   ///< the library's message for subject_now_
  bool running_ = false;
  std::thread thread_;
  QElapsedTimer since_change_;  ///< since the newest change asked for
  std::optional<WhatIfResult> shown_;
  std::optional<Request> answered_;  ///< what the sentence answers (a result or a message)
  bool setting_sliders_ = false;
  double last_latency_ms_ = 0.0;
  std::vector<double> latencies_ms_;
  double last_flight_ms_ = 0.0;
};

}  // namespace saltus::gui
