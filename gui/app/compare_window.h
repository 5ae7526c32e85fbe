#pragma once
/// @file
/// Two runs side by side: two 3D views driven by one timeline, and the root force and moment of
/// both overlaid (first run solid blue, second dashed orange). The runs are Documents the main
/// window loaded and evaluated through the library exactly as its own; this window only shows
/// them. Qt types only in this header.

#include <QMainWindow>
#include <QString>
#include <array>
#include <memory>

#include "core/chart_spec.h"
#include "core/document.h"
#include "core/scene_options.h"

class QComboBox;
class QImage;
class QLabel;

namespace saltus::gui {

class ChartWidget;
class SceneWidget;
class TimelineWidget;

class CompareWindow : public QMainWindow {
  Q_OBJECT

 public:
  /// One side of the comparison: a loaded document, the stage to show, and its name in titles
  /// and legends.
  struct Run {
    QString label;
    std::shared_ptr<const Document> document;
    Stage stage = Stage::kBefore;
  };

  explicit CompareWindow(QWidget* parent = nullptr);
  ~CompareWindow() override;

  /// Shows two runs (both documents loaded); the timeline starts at 0.
  void set_runs(Run first, Run second);
  const Run& run(int index) const { return runs_.at(static_cast<std::size_t>(index)); }
  /// The main window's display options, without keyframe ghosts and physics text.
  void set_scene_options(const SceneOptions& options);
  void set_camera(CameraPreset preset);

  void seek(double t);
  double time() const;
  /// The 3D view of run 0 or 1 as it is now.
  QImage grab_view(int index);
  /// The overlay charts as shown (root force, root moment).
  const ChartSpec& force_chart() const;
  const ChartSpec& moment_chart() const;

 private:
  void refresh_charts();
  void on_time_changed(double t);

  std::array<Run, 2> runs_;
  std::array<SceneWidget*, 2> scenes_{};
  std::array<QLabel*, 2> titles_{};
  TimelineWidget* timeline_ = nullptr;
  ChartWidget* force_chart_ = nullptr;
  ChartWidget* moment_chart_ = nullptr;
  QComboBox* components_ = nullptr;
};

}  // namespace saltus::gui
