#pragma once
/// @file
/// Optimisation runs: the Optimise menu (Run, Ctrl+R; Cancel, Esc), the Optimise panel, the
/// worker thread, and the result list. Every finished run is kept in the workspace's RunList;
/// which one is shown follows RunList::preferred, so a cancelled or failed run never replaces a
/// solved one (it is listed, and shown only when the user picks it). Messages say what happened
/// in words ("cancelled after 12 iterations: 90 N, worse than the solved run 2 (13.1 N), which
/// stays shown").

#include <QObject>
#include <QString>

#include "app/app_context.h"
#include "core/optimize_settings.h"

class QAction;
class QMenu;

namespace saltus::gui {

class OptimizationRunner;
class OptimizePanel;

class RunController : public QObject, public RemembersSettings {
  Q_OBJECT

 public:
  RunController(AppContext& context, QObject* parent = nullptr);

  void fill_menu(QMenu* optimise);
  OptimizePanel* panel() const { return panel_; }

  /// Starts optimising the open motion in the background.
  bool start(const OptimizeSettings& settings, QString* error = nullptr);
  /// Stops the running optimisation at its next iteration (its iterate is kept as a run).
  void cancel();
  bool running() const;
  /// Keeps the event loop running until the run ends or `timeout_ms` pass; whether it ended.
  bool wait(int timeout_ms);
  /// The panel's current values.
  OptimizeSettings settings() const;
  /// Shows run `index` of the list (-1: none); false if it has no result.
  bool show_run(int index, QString* error = nullptr);

  void load_settings(const QSettings& settings) override;
  void save_settings(QSettings& settings) const override;

 signals:
  /// A run ended: `ok` when it returned a result (whatever its status).
  void finished(bool ok);

 private:
  void on_workspace(WorkspaceChange change);
  void on_finished(int tag, bool ok, const QString& error);
  void update_actions();
  void show_list();

  AppContext& context_;
  OptimizePanel* panel_ = nullptr;
  OptimizationRunner* runner_ = nullptr;
  QAction* run_ = nullptr;
  QAction* cancel_ = nullptr;
  OptimizeSettings running_settings_;
  OptimizeOptions running_options_;
};

}  // namespace saltus::gui
