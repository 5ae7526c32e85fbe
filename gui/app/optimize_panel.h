#pragma once
/// @file
/// The optimisation panel: the option table's options (OptionForm); Run and Cancel; live
/// progress; the result table (before / after).

#include <QWidget>
#include <vector>

#include "core/optimize_settings.h"

class QLabel;
class QProgressBar;
class QPushButton;
class QTableWidget;

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
  void show_result(const std::vector<ResultRow>& rows);
  void clear_result();

 signals:
  void run_requested();
  void cancel_requested();

 private:
  void update_enabled();

  OptionForm* form_ = nullptr;
  QPushButton* run_ = nullptr;
  QPushButton* cancel_ = nullptr;
  QProgressBar* bar_ = nullptr;
  QLabel* status_ = nullptr;
  QTableWidget* table_ = nullptr;
  bool available_ = false;
  bool running_ = false;
};

}  // namespace saltus::gui
