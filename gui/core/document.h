#pragma once
/// @file
/// The open motion and everything the views show about it: the model, the evaluation of the
/// interpolated keyframes ("before"), the optimisation result ("after") when there is one, the
/// rotation metrics of both and the glyph scales. All numbers come from library calls; the
/// views only ask for them.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/glyph_scale.h"
#include "core/parabola.h"
#include "core/plot_series.h"
#include "saltus/evaluation/evaluate.h"
#include "saltus/evaluation/flight_checks.h"
#include "saltus/evaluation/rotation_metrics.h"
#include "saltus/optim/optimize.h"
#include "saltus/use_cases/captures.h"

namespace saltus::gui {

/// Which version of the motion: the keyframe interpolation, or the optimised one.
enum class Stage { kBefore, kAfter };

/// Typical sizes of what the arrows show, for their scales (GlyphScale): the 90th percentile
/// over the samples of a stage (one spike at an end of the flight must not shrink every other
/// arrow to nothing).
struct GlyphTypicals {
  double residual_force = 0.0;   ///< N
  double residual_moment = 0.0;  ///< N·m
  double joint_force = 0.0;      ///< N, the largest joint force of a sample (root excluded)
  /// The larger of each, e.g. for two views that must share one scale.
  GlyphTypicals max(const GlyphTypicals& other) const;
};

/// "forward" or "backward" for a somersault count so far, `now` (revolutions, > 0 forward):
/// its own sign, or, before it shows (below 0.005, which reads "0.00"), the whole flight's
/// (`flight`): M2 at take-off reads "0.00 somersaults backward", as it will turn.
std::string somersault_direction(double now, double flight);

class Document {
 public:
  /// Loads a motion file and the model it names and evaluates it with `samples` time samples.
  /// With `model_override` (a name or path) the motion is flown by that athlete as the CLI's
  /// `--model` flies it (load_motion_for_athlete, its default take-off rule: the same take-off
  /// spin; file().takeoff_adaptation says so). A motion capture (a .bvh path, is_capture_path)
  /// is imported onto the model (import_capture_file with `capture_options`: the defaults of
  /// `saltus import` unless given; their model is the override): the motion is its picked
  /// keyframes, and the capture stays (capture()). Throws InputError for
  /// bad files and std::invalid_argument for bad options; on failure the document keeps what it
  /// had.
  void load(const std::string& motion_path, const std::string& model_override = "",
            int samples = kDefaultSamples, const CaptureFileOptions& capture_options = {});
  bool loaded() const { return file_.has_value(); }
  /// Replaces the loaded motion by an edited one (same model, file path and samples) and
  /// evaluates it; drops the optimisation. Requires loaded(); on failure nothing changes.
  void set_motion(const Motion& motion);
  /// Replaces the model by an edited one with the same segments (e.g. other masses) and
  /// re-evaluates the motion; drops the optimisation. On failure nothing changes.
  void set_model(const BodyModel& model);
  /// Both at once, evaluated once (undo and redo of an edit). On failure nothing changes.
  void set_motion_and_model(const Motion& motion, const BodyModel& model);
  /// The model as loaded (before any set_model): mass factors are relative to it.
  const BodyModel& loaded_model() const { return loaded_model_; }
  /// Whether the motion or the model was edited since it was loaded.
  bool edited() const { return edited_; }
  /// The loaded motion and model; requires loaded().
  const MotionFile& file() const { return *file_; }
  const std::string& model_override() const { return model_override_; }
  const EvaluateOptions& evaluate_options() const { return evaluate_options_; }

  bool has_optimization() const { return optimization_.has_value(); }
  const OptimizationResult& optimization() const { return *optimization_; }
  const OptimizeOptions& optimization_options() const { return optimize_options_; }
  /// Installs an optimisation result of this document's motion (from optimize_motion).
  void set_optimization(OptimizationResult result, const OptimizeOptions& options);
  void clear_optimization();

  /// A stage that exists: kAfter only with an optimisation, else kBefore.
  Stage available(Stage wanted) const;
  /// The evaluation of a stage. With an optimisation both stages come from it (one sample grid);
  /// otherwise kBefore is the document's own evaluation.
  const MotionEvaluation& evaluation(Stage stage) const;
  /// The stage on the dense plot grid (kPlotSamples samples over the flight), its rotation
  /// quantities and its flight checks.
  const std::vector<SampleRecord>& plot_samples(Stage stage) const;
  const std::vector<RotationSample>& rotation(Stage stage) const;
  const FlightChecks& flight_checks(Stage stage) const;

  double duration() const { return file_->motion.flight_time(); }
  /// Sample grid size of a stage (the timeline's frames).
  int frame_count(Stage stage) const;

  /// The exact state at time t: one inverse-dynamics evaluation of the stage's trajectory.
  SampleRecord sample_at(Stage stage, double t) const;
  /// Rotation quantities at t: instantaneous values exact at t, counts interpolated along the
  /// stage's sample grid.
  RotationSample rotation_at(Stage stage, double t) const;
  /// Poses at the keyframe times of a stage (given times before, optimised times after).
  std::vector<SampleRecord> keyframe_poses(Stage stage) const;
  /// The ballistic CoM path of the take-off state over the flight.
  ParabolaSamples parabola(int count) const;

  /// Typical arrow sizes of one stage alone.
  GlyphTypicals glyph_typicals(Stage stage) const;
  /// The arrows' sizes for both stages of the run shown: the larger stage's (before, in
  /// practice), so that one scale draws before and after and the 0.5 N left after optimisation
  /// is drawn a thousandth as long as the 500 N before, not as large and as red. Without a run,
  /// the interpolated motion's.
  GlyphTypicals arrow_typicals() const;

  /// The motion capture the motion was imported from, null for a motion file. Its frames can be
  /// picked as keyframes (core/capture_keyframes.h); it is drawn beside the motion.
  const CaptureFile* capture() const { return capture_.get(); }
  /// The options the capture was imported with (its frame time, flight, keyframes, mapping).
  const CaptureFileOptions& capture_options() const { return capture_options_; }
  /// The captured flight's length (s): its own trajectory is defined on [0, capture_duration()].
  double capture_duration() const;
  /// The capture's own motion on the dense plot grid, with the model in use (a mass edit
  /// changes its residual as it changes the motion's): how physically correct the capture is.
  /// Empty without a capture.
  const std::vector<SampleRecord>& capture_plot_samples() const { return capture_samples_; }
  /// The capture at time t of the motions' clock (clamped to its flight): one inverse-dynamics
  /// evaluation of its own trajectory. Requires capture().
  SampleRecord capture_sample_at(double t) const;

  /// Writes the outputs the CLI would: `saltus optimize`'s when optimised, else `saltus
  /// evaluate`'s (result.json, trajectories, model.json, ...), all or nothing.
  void save_result(const std::string& out_dir) const;

 private:
  std::optional<MotionFile> file_;
  std::string model_override_;
  bool edited_ = false;
  BodyModel loaded_model_;
  EvaluateOptions evaluate_options_;
  /// What the plots and the teaching view read of one stage.
  struct Dense {
    std::vector<SampleRecord> samples;
    std::vector<RotationSample> rotation;
    FlightChecks checks;
  };
  static Dense dense_of(const MotionFile& file, const MotionEvaluation& evaluation);
  const Dense& dense(Stage stage) const;

  static std::vector<SampleRecord> capture_samples_of(const CaptureFile* capture,
                                                      const BodyModel& model);

  MotionEvaluation evaluation_;
  Dense dense_;
  std::shared_ptr<const CaptureFile> capture_;  ///< immutable: shared by copies and snapshots
  CaptureFileOptions capture_options_;
  std::vector<SampleRecord> capture_samples_;
  std::optional<OptimizationResult> optimization_;
  OptimizeOptions optimize_options_;
  Dense dense_opt_before_;
  Dense dense_opt_after_;
};

}  // namespace saltus::gui
