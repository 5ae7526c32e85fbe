#include "app/optimization_runner.h"

#include <QMetaObject>
#include <exception>
#include <memory>

namespace saltus::gui {

OptimizationRunner::OptimizationRunner(QObject* parent) : QObject(parent) {
  qRegisterMetaType<saltus::ProgressInfo>("saltus::ProgressInfo");
}

OptimizationRunner::~OptimizationRunner() {
  cancel_ = true;
  if (thread_.joinable()) thread_.join();
}

bool OptimizationRunner::start(const MotionFile& file, const OptimizeOptions& options, int tag) {
  if (running_) return false;
  if (thread_.joinable()) thread_.join();
  running_ = true;
  cancel_ = false;
  result_.reset();
  thread_ = std::thread([this, file, options, tag] {
    // Queued calls with `this` as context run on the GUI thread and are dropped if the runner
    // is destroyed first (its destructor joins this thread before that can happen anyway).
    const ProgressCallback on_progress = [this](const ProgressInfo& info) {
      QMetaObject::invokeMethod(
          this, [this, info] { emit progress(info); }, Qt::QueuedConnection);
    };
    auto result = std::make_shared<std::optional<OptimizationResult>>();
    QString error;
    try {
      *result = optimize_motion(file.motion, file.model, options, on_progress, &cancel_);
    } catch (const std::exception& e) {
      error = QString::fromStdString(e.what());
    }
    QMetaObject::invokeMethod(
        this,
        [this, result, error, tag] {
          if (thread_.joinable()) thread_.join();
          running_ = false;
          result_ = std::move(*result);
          emit finished(tag, result_.has_value(), error);
        },
        Qt::QueuedConnection);
  });
  return true;
}

void OptimizationRunner::cancel() {
  cancel_ = true;
}

std::optional<OptimizationResult> OptimizationRunner::take_result() {
  std::optional<OptimizationResult> out = std::move(result_);
  result_.reset();
  return out;
}

}  // namespace saltus::gui
