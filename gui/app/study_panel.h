#pragma once
/// @file
/// The Study panel (a tab of the panel column, shown when a study starts): the running study's
/// progress (bar, cases done, failures, elapsed time, time left, the last case) with Stop, and
/// once it has ended what it came to: a chart of the cases solved per model, Open folder and
/// Open report. Its tables, the library's summary per model (convergence.md's) and one row per
/// case, need more width than the panel column has: they are a tab of their own under the 3D
/// view, beside the plots (tables()). Nothing of it covers the 3D view, which stays usable
/// (playback, camera) while the study runs. The controller (StudyController) fills it; the
/// panel only shows and asks.

#include <QWidget>

#include "core/study_results.h"
#include "saltus/formats/study_progress.h"

class QLabel;
class QProgressBar;
class QPushButton;
class QTableWidget;

namespace saltus::gui {

class ChartWidget;

class StudyPanel : public QWidget {
  Q_OBJECT

 public:
  explicit StudyPanel(QWidget* parent = nullptr);

  /// A study starts into `folder` (the results of the one before are cleared).
  void show_started(const QString& title, const QString& folder, const QString& first_words);
  void show_progress(const StudyProgressLine& progress);
  /// The study ended: `outcome` in words, in red when `failure`; Stop gives way to the results.
  void show_ended(const QString& outcome, bool failure);
  /// What the study's folder holds (a finished study, or the cases a stopped one kept).
  void show_results(const ConvergenceStudyFolder& folder);
  void clear_results();

  /// The progress in words: "3 of 8 cases · 0 failed · 1 not solved · 0:41 elapsed · about
  /// 1:02 left" (also the status bar's).
  static QString progress_text(const StudyProgressLine& progress);

  QProgressBar* progress_bar() const { return bar_; }
  QLabel* progress_label() const { return progress_; }
  QLabel* outcome_label() const { return outcome_; }
  QPushButton* stop_button() const { return stop_; }
  QPushButton* open_folder_button() const { return open_folder_; }
  QPushButton* open_report_button() const { return open_report_; }
  /// The summary and the cases side by side, for the tab under the 3D view ("Study results").
  QWidget* tables() const { return tables_; }
  QTableWidget* summary_table() const { return summary_; }
  QTableWidget* case_table() const { return cases_; }
  ChartWidget* chart() const { return chart_; }

 signals:
  void stop_requested();
  void open_folder_requested();
  void open_report_requested();

 private:
  QLabel* title_ = nullptr;
  QLabel* folder_ = nullptr;
  QProgressBar* bar_ = nullptr;
  QLabel* progress_ = nullptr;
  QLabel* last_ = nullptr;
  QPushButton* stop_ = nullptr;
  QLabel* outcome_ = nullptr;
  QWidget* results_ = nullptr;
  QLabel* results_line_ = nullptr;
  ChartWidget* chart_ = nullptr;
  QWidget* tables_ = nullptr;
  QTableWidget* summary_ = nullptr;
  QTableWidget* cases_ = nullptr;
  QPushButton* open_folder_ = nullptr;
  QPushButton* open_report_ = nullptr;
};

}  // namespace saltus::gui
