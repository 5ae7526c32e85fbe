#pragma once
/// @file
/// The Twist panel: where the twist of the motion shown comes from (the library's
/// `twist_sources`): its sentence, a table of each source's tilt and share, and a chart of the
/// tilt over time of the actual flight and of each counterfactual. It computes on a worker
/// thread (about a second for a twisting double), only while the panel is in view, and never
/// shows a result for another motion than the one shown: a change of motion, model, edit or run
/// clears it until the new one is ready (results already computed are kept and shown at once).

#include <QString>
#include <QWidget>
#include <optional>
#include <thread>
#include <vector>

#include "app/app_context.h"
#include "core/shown_motion.h"
#include "core/twist_report.h"

class QLabel;
class QTableWidget;

namespace saltus::gui {

class ChartWidget;

class TwistPanel : public QWidget {
  Q_OBJECT

 public:
  explicit TwistPanel(AppContext& context, QWidget* parent = nullptr);
  /// Waits for a computation still running (its result is dropped).
  ~TwistPanel() override;

  /// In view or not (its dock raised or hidden): computes only in view.
  void set_active(bool active);
  /// Moves the chart's time cursor.
  void set_time(double t);

  /// Whether the result for the motion shown is still being worked out (tests wait on it).
  bool busy() const;
  /// What is shown (tests): the library's sentence (or the message shown instead), which motion
  /// it is about, the table and the chart.
  QString sentence() const;
  QString subject() const;
  QTableWidget* table() const { return table_; }
  ChartWidget* chart() const { return chart_; }
  /// Wall time of the last twist_sources call, s.
  double last_seconds() const { return last_seconds_; }

 signals:
  void seek_requested(double t);
  /// A result (or the library's message) for the motion shown is on screen.
  void result_shown();

 private:
  struct Result {
    ShownMotion::Key key;
    std::optional<TwistSources> sources;  ///< empty: the library threw `error`
    QString error;
  };

  void refresh();
  void start(const ShownMotion& subject);
  void on_finished(Result result, double seconds);
  void show_result(const Result& result);
  void show_message(const QString& text);
  const Result* cached(const ShownMotion::Key& key) const;

  AppContext& context_;
  QLabel* subject_ = nullptr;
  QLabel* sentence_ = nullptr;
  QLabel* summary_ = nullptr;
  QTableWidget* table_ = nullptr;
  QLabel* method_ = nullptr;
  QWidget* chart_box_ = nullptr;
  ChartWidget* chart_ = nullptr;

  bool active_ = false;
  std::optional<ShownMotion::Key> wanted_;  ///< the motion shown; none without one
  std::optional<ShownMotion::Key> running_;
  std::thread thread_;
  /// The last few results, newest last: B/A and picking runs show them again at once.
  std::vector<Result> cache_;
  double last_seconds_ = 0.0;
};

}  // namespace saltus::gui
