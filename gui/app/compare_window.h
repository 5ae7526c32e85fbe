#pragma once
/// @file
/// Two runs side by side: two 3D views driven by one timeline, on one scale (framed for the
/// taller athlete) and with one arrow scale for both (the larger run's), the root force and moment
/// of both overlaid (resultants by default, components on demand, a log scale), and the loads at
/// any joint of both (the paper's Fig. 8, for any joint and any pair of runs). Curves follow the
/// plots' one style: the first run dashed blue, the second solid orange. The runs are Documents the
/// main window loaded and evaluated through the library exactly as its own; this window only shows
/// them. Qt types only in this header.

#include <QMainWindow>
#include <QString>
#include <array>
#include <memory>
#include <optional>

#include "core/athlete_landing.h"
#include "core/chart_spec.h"
#include "core/document.h"
#include "core/scene_options.h"

class QCheckBox;
class QComboBox;
class QImage;
class QLabel;
class QTabWidget;

namespace saltus::gui {

class ChartWidget;
class SceneWidget;
class TimelineWidget;

class CompareWindow : public QMainWindow {
  Q_OBJECT

 public:
  /// One side of the comparison: a loaded document, the stage to show, its name in legends and
  /// what it is ("optimised, run 2", "interpolated keyframes", "optimised motion (saltus
  /// optimize folder)").
  struct Run {
    QString label;
    std::shared_ptr<const Document> document;
    Stage stage = Stage::kBefore;
    QString description;
    /// When two athletes are compared: can this one land it (core/athlete_landing.h). Its
    /// verdict leads the side's title, and its free flight is drawn beside the athlete, so that
    /// both land side by side at the end of the timeline.
    std::optional<AthleteLanding> landing;
  };

  explicit CompareWindow(QWidget* parent = nullptr);
  ~CompareWindow() override;

  /// Shows two runs (both documents loaded); the timeline starts at 0 unless `keep_time`.
  void set_runs(Run first, Run second, bool keep_time = false);
  const Run& run(int index) const { return runs_.at(static_cast<std::size_t>(index)); }
  /// A line under the views (e.g. "optimising the second run…"); empty hides it.
  void set_note(const QString& note);
  /// The main window's display options, without keyframe ghosts and the numbers.
  void set_scene_options(const SceneOptions& options);
  void set_camera(CameraPreset preset);

  void seek(double t);
  double time() const;
  /// The 3D view of run 0 or 1 as it is now.
  QImage grab_view(int index);
  /// A side's title as shown (rich text).
  QString title(int index) const;
  /// The whole window (batch --compare --screenshot).
  QImage grab_window();
  /// The charts as shown (root force, root moment, joint force, joint moment).
  const ChartSpec& force_chart() const;
  const ChartSpec& moment_chart() const;
  const ChartSpec& joint_force_chart() const;
  const ChartSpec& joint_moment_chart() const;
  /// Shows the loads at a segment's joint (switching to that tab).
  void show_joint(int segment);
  /// The arrow scales both views share (the larger run's typical sizes).
  GlyphTypicals shared_glyph_typicals() const;

 private:
  void refresh_charts();
  void refresh_joint_charts();
  void on_time_changed(double t);

  std::array<Run, 2> runs_;
  std::array<SceneWidget*, 2> scenes_{};
  std::array<QLabel*, 2> titles_{};
  QLabel* note_ = nullptr;
  TimelineWidget* timeline_ = nullptr;
  QTabWidget* tabs_ = nullptr;
  ChartWidget* force_chart_ = nullptr;
  ChartWidget* moment_chart_ = nullptr;
  ChartWidget* joint_force_chart_ = nullptr;
  ChartWidget* joint_moment_chart_ = nullptr;
  QComboBox* joint_ = nullptr;
  QComboBox* components_ = nullptr;
  QCheckBox* log_scale_ = nullptr;
  GlyphTypicals typicals_;
};

}  // namespace saltus::gui
