#pragma once
/// @file
/// The optimisation panel: the option table's options (OptionForm: one row each); Run and Cancel;
/// live progress (RunProgress: the stage, the iteration, the time left, what the objective
/// means); the list of runs of this motion, best first (each kept; choosing one shows it) and
/// the result table of the run shown (before / after). It only asks: the run controller optimises,
/// the edit controller makes option changes undoable.

#include <QWidget>
#include <string>
#include <utility>
#include <vector>

#include "core/optimize_settings.h"
#include "core/run_progress.h"

class QLabel;
class QListWidget;
class QProgressBar;
class QPushButton;
class QTableWidget;
class QTabWidget;

namespace saltus::gui {

class OptionForm;

class OptimizePanel : public QWidget {
  Q_OBJECT

 public:
  explicit OptimizePanel(QWidget* parent = nullptr);

  OptimizeSettings settings() const;
  void set_settings(const OptimizeSettings& settings);
  /// Whether Run is possible at all (a motion is open).
  void set_available(bool available);
  /// Switches between the idle and the running look (Run / Cancel, progress).
  void set_running(bool running);
  void show_progress(const ProgressInfo& progress);
  /// Ends the progress display with a message (finished, cancelled, failed).
  void show_message(const QString& message);
  /// The message shown under the progress bar.
  QString message() const;
  void show_result(const std::vector<ResultRow>& rows);
  void clear_result();
  /// A run's line in the list: its index, its words, and its words with its settings (the
  /// tooltip).
  struct RunRow {
    int index = -1;
    std::string label;
    std::string details;
  };
  /// The run list: one line per run in the order given (best first), the run `shown`
  /// highlighted (-1: none, the interpolation).
  void show_runs(const std::vector<RunRow>& runs, int shown);
  QListWidget* run_list() const { return runs_; }
  /// The before/after table and the options, as tabs (after a run the table is in front).
  QTabWidget* details() const { return details_; }
  /// The list's row of a run (0 is "interpolated keyframes only"), -1 when not listed.
  int row_of_run(int index) const;
  /// The progress of the run under way (or the last one).
  const RunProgress& progress() const { return progress_; }
  /// Clears the progress, the message, the list and the table (another motion was opened).
  void reset();

 signals:
  void run_requested();
  void cancel_requested();
  /// The user picked a run in the list (-1: "interpolation only").
  void run_chosen(int index);
  /// The user changed a value: what it was and what it is now (for undo).
  void settings_edited(const saltus::gui::OptimizeSettings& before,
                       const saltus::gui::OptimizeSettings& after);

 private:
  void update_enabled();

  OptionForm* form_ = nullptr;
  QPushButton* run_ = nullptr;
  QPushButton* cancel_ = nullptr;
  QProgressBar* bar_ = nullptr;
  QLabel* status_ = nullptr;
  QLabel* time_left_ = nullptr;
  QLabel* objective_ = nullptr;
  RunProgress progress_;
  QTableWidget* table_ = nullptr;
  QTabWidget* details_ = nullptr;  ///< the table and the options, one in front
  QListWidget* runs_ = nullptr;
  bool available_ = false;
  bool running_ = false;
  bool setting_ = false;  ///< show_runs is filling the list: no run_chosen
};

}  // namespace saltus::gui
