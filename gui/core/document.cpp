#include "core/document.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "saltus/formats/motion_file.h"
#include "saltus/formats/result_json.h"
#include "saltus/use_cases/athlete_models.h"
#include "saltus/use_cases/result_folders.h"

namespace saltus::gui {

GlyphTypicals GlyphTypicals::max(const GlyphTypicals& other) const {
  return {std::max(residual_force, other.residual_force),
          std::max(residual_moment, other.residual_moment),
          std::max(joint_force, other.joint_force)};
}

Document::Dense Document::dense_of(const MotionFile& file, const MotionEvaluation& evaluation) {
  Dense out;
  const double duration =
      evaluation.samples.empty() ? file.motion.flight_time() : evaluation.samples.back().time;
  out.samples = evaluate_trajectory(file.model, evaluation.trajectory,
                                    uniform_times(duration, plot_samples_for(duration)));
  out.rotation = rotation_metrics(file.model, out.samples);
  out.checks = saltus::flight_checks(file.motion.takeoff, out.samples);
  return out;
}

std::string somersault_direction(double now, double flight) {
  const double sign = std::abs(now) >= 0.005 ? now : flight;
  return sign < 0 ? "backward" : "forward";
}

void Document::load(const std::string& motion_path, const std::string& model_override, int samples,
                    const CaptureFileOptions& capture_options) {
  MotionFile file;
  std::shared_ptr<const CaptureFile> capture;
  if (is_capture_path(motion_path)) {
    // As load_motion_or_capture reads a capture, keeping the import for the views.
    CaptureFileOptions options = capture_options;
    options.model = model_override;
    auto imported = std::make_shared<CaptureFile>(import_capture_file(motion_path, options));
    file.path = motion_path;
    file.model = imported->model;
    file.motion = imported->import.keyframes;
    file.motion.model = imported->model_reference;
    capture = std::move(imported);
  }
  if (!model_override.empty()) {
    // Another athlete: the take-off carried over by the CLI's rule (for a capture, its picked
    // keyframes with that take-off; the import above stays for the views).
    MotionFile athlete = load_motion_for_athlete(motion_path, model_override,
                                                 TakeoffRule::kSameSpin, capture_options);
    if (capture) {
      file.motion.takeoff = athlete.motion.takeoff;
      file.takeoff_adaptation = athlete.takeoff_adaptation;
    } else {
      file = std::move(athlete);
    }
  } else if (!capture) {
    file = load_motion_file(motion_path);
  }
  EvaluateOptions options;
  options.samples = samples;
  MotionEvaluation evaluation = evaluate_motion(file.motion, file.model, options);
  Dense dense = dense_of(file, evaluation);
  std::vector<SampleRecord> capture_samples = capture_samples_of(capture.get(), file.model);
  // Only now that everything succeeded does the document change.
  file_ = std::move(file);
  model_override_ = model_override;
  capture_options_ = capture ? capture_options : CaptureFileOptions{};
  capture_options_.model.clear();
  evaluate_options_ = options;
  evaluation_ = std::move(evaluation);
  dense_ = std::move(dense);
  edited_ = false;
  loaded_model_ = file_->model;
  capture_ = std::move(capture);
  capture_samples_ = std::move(capture_samples);
  clear_optimization();
}

double Document::capture_duration() const {
  return capture_ ? capture_->import.captured.flight_time() : 0.0;
}

std::vector<SampleRecord> Document::capture_samples_of(const CaptureFile* capture,
                                                       const BodyModel& model) {
  if (!capture) return {};
  const double duration = capture->import.captured.flight_time();
  return evaluate_trajectory(model, capture->import.trajectory,
                             uniform_times(duration, plot_samples_for(duration)));
}

SampleRecord Document::capture_sample_at(double t) const {
  if (!capture_) throw std::logic_error("no capture");
  const double clamped = std::clamp(t, 0.0, capture_duration());
  return evaluate_trajectory(file_->model, capture_->import.trajectory, {clamped}).front();
}

void Document::set_model(const BodyModel& model) {
  if (!loaded()) throw std::logic_error("no motion loaded");
  set_motion_and_model(file_->motion, model);
}

void Document::set_motion(const Motion& motion) {
  if (!loaded()) throw std::logic_error("no motion loaded");
  set_motion_and_model(motion, file_->model);
}

void Document::set_motion_and_model(const Motion& motion, const BodyModel& model) {
  if (!loaded()) throw std::logic_error("no motion loaded");
  if (model.size() != file_->model.size())
    throw std::invalid_argument("the edited model has other segments than the motion's");
  MotionFile file = *file_;
  file.motion = motion;
  file.model = model;
  MotionEvaluation evaluation = evaluate_motion(motion, model, evaluate_options_);
  Dense dense = dense_of(file, evaluation);
  // The capture's residual depends on the masses.
  std::vector<SampleRecord> capture_samples = capture_samples_of(capture_.get(), model);
  file_ = std::move(file);
  evaluation_ = std::move(evaluation);
  dense_ = std::move(dense);
  edited_ = true;
  capture_samples_ = std::move(capture_samples);
  clear_optimization();
}

void Document::set_optimization(OptimizationResult result, const OptimizeOptions& options) {
  if (!loaded()) throw std::logic_error("no motion loaded");
  dense_opt_before_ = dense_of(*file_, result.before);
  dense_opt_after_ = dense_of(*file_, result.after);
  optimization_ = std::move(result);
  optimize_options_ = options;
}

void Document::clear_optimization() {
  optimization_.reset();
  dense_opt_before_ = Dense{};
  dense_opt_after_ = Dense{};
}

Stage Document::available(Stage wanted) const {
  return wanted == Stage::kAfter && has_optimization() ? Stage::kAfter : Stage::kBefore;
}

const MotionEvaluation& Document::evaluation(Stage stage) const {
  if (!has_optimization()) return evaluation_;
  return stage == Stage::kAfter ? optimization_->after : optimization_->before;
}

const Document::Dense& Document::dense(Stage stage) const {
  if (!has_optimization()) return dense_;
  return stage == Stage::kAfter ? dense_opt_after_ : dense_opt_before_;
}

const std::vector<SampleRecord>& Document::plot_samples(Stage stage) const {
  return dense(stage).samples;
}

const std::vector<RotationSample>& Document::rotation(Stage stage) const {
  return dense(stage).rotation;
}

const FlightChecks& Document::flight_checks(Stage stage) const {
  return dense(stage).checks;
}

int Document::frame_count(Stage stage) const {
  return static_cast<int>(evaluation(available(stage)).samples.size());
}

SampleRecord Document::sample_at(Stage stage, double t) const {
  const double clamped = std::clamp(t, 0.0, duration());
  return evaluate_trajectory(file_->model, evaluation(available(stage)).trajectory, {clamped})
      .front();
}

RotationSample Document::rotation_at(Stage stage, double t) const {
  const SampleRecord record = sample_at(stage, t);
  RotationSample out = rotation_metrics(file_->model, {record}).front();
  const std::vector<RotationSample>& series = rotation(available(stage));
  if (series.empty()) return out;
  // Counts are integrals along the grid: interpolate them linearly between grid samples.
  const auto after =
      std::lower_bound(series.begin(), series.end(), out.time,
                       [](const RotationSample& s, double time) { return s.time < time; });
  if (after == series.begin()) {
    out.somersaults = series.front().somersaults;
    out.twists = series.front().twists;
  } else if (after == series.end()) {
    out.somersaults = series.back().somersaults;
    out.twists = series.back().twists;
  } else {
    const RotationSample& a = *(after - 1);
    const RotationSample& b = *after;
    const double u = b.time > a.time ? (out.time - a.time) / (b.time - a.time) : 0.0;
    out.somersaults = a.somersaults + u * (b.somersaults - a.somersaults);
    out.twists = a.twists + u * (b.twists - a.twists);
  }
  return out;
}

std::vector<SampleRecord> Document::keyframe_poses(Stage stage) const {
  const MotionEvaluation& e = evaluation(available(stage));
  return evaluate_trajectory(file_->model, e.trajectory, e.keyframe_times);
}

ParabolaSamples Document::parabola(int count) const {
  return sample_parabola(file_->motion.takeoff, duration(), count);
}

namespace {
constexpr double kScalePercentile = 0.9;

template <typename Measure>
double typical(const std::vector<SampleRecord>& samples, Measure measure) {
  std::vector<double> values;
  values.reserve(samples.size());
  for (const SampleRecord& s : samples)
    values.push_back(measure(s));
  if (values.empty()) return 0.0;
  const std::size_t k = static_cast<std::size_t>(kScalePercentile * (values.size() - 1) + 0.5);
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(k), values.end());
  return values[k];
}

double largest_joint_force(const SampleRecord& s) {
  double m = 0.0;
  for (std::size_t i = 1; i < s.joint_wrench.size(); ++i)
    m = std::max(m, s.joint_wrench[i].head<3>().norm());
  return m;
}
}  // namespace

GlyphTypicals Document::glyph_typicals(Stage stage) const {
  const std::vector<SampleRecord>& samples = evaluation(available(stage)).samples;
  GlyphTypicals out;
  out.residual_force =
      typical(samples, [](const SampleRecord& s) { return s.residual.head<3>().norm(); });
  out.residual_moment =
      typical(samples, [](const SampleRecord& s) { return s.residual.tail<3>().norm(); });
  out.joint_force = typical(samples, largest_joint_force);
  return out;
}

GlyphTypicals Document::arrow_typicals() const {
  const GlyphTypicals before = glyph_typicals(Stage::kBefore);
  return has_optimization() ? before.max(glyph_typicals(Stage::kAfter)) : before;
}

void Document::save_result(const std::string& out_dir) const {
  if (!loaded()) throw std::logic_error("no motion loaded");
  if (has_optimization())
    write_optimization_outputs(out_dir, *file_, *optimization_, optimize_options_);
  else
    write_evaluation_outputs(out_dir, *file_, evaluation_, evaluate_options_);
}

}  // namespace saltus::gui
