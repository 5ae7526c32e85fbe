#pragma once
/// @file
/// Runs optimize_motion in a worker thread so the window never freezes: progress arrives once
/// per iteration and the result at the end as queued signals on the GUI thread; cancel() sets
/// the library's cancel flag, which stops Ipopt at its next iteration.

#include <QObject>
#include <QString>
#include <atomic>
#include <optional>
#include <thread>

#include "saltus/optim/optimize.h"

namespace saltus::gui {

class OptimizationRunner : public QObject {
  Q_OBJECT

 public:
  explicit OptimizationRunner(QObject* parent = nullptr);
  /// Cancels a running optimisation and waits for its thread (at most one Ipopt iteration).
  ~OptimizationRunner() override;

  bool running() const { return running_; }
  /// Starts optimising a copy of `file` (the caller may change its own meanwhile). `tag`
  /// comes back with finished() so the caller can tell whether the result still applies.
  /// Returns false if one is already running.
  bool start(const MotionFile& file, const OptimizeOptions& options, int tag);
  void cancel();
  /// The result after finished(ok = true); empty otherwise or once taken.
  std::optional<OptimizationResult> take_result();

 signals:
  void progress(const saltus::ProgressInfo& info);
  /// ok false: the library threw; `error` says why.
  void finished(int tag, bool ok, const QString& error);

 private:
  std::thread thread_;
  std::atomic<bool> cancel_{false};
  bool running_ = false;
  std::optional<OptimizationResult> result_;
};

}  // namespace saltus::gui

Q_DECLARE_METATYPE(saltus::ProgressInfo)
