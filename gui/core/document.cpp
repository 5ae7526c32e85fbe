#include "core/document.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "saltus/formats/motion_file.h"
#include "saltus/formats/result_json.h"

namespace saltus::gui {

void Document::load(const std::string& motion_path, const std::string& model_override,
                    int samples) {
  MotionFile file = load_motion_file(motion_path, model_override);
  EvaluateOptions options;
  options.samples = samples;
  MotionEvaluation evaluation = evaluate_motion(file.motion, file.model, options);
  std::vector<RotationSample> rotation = rotation_metrics(file.model, evaluation.samples);
  // Only now that everything succeeded does the document change.
  file_ = std::move(file);
  model_override_ = model_override;
  evaluate_options_ = options;
  evaluation_ = std::move(evaluation);
  rotation_ = std::move(rotation);
  edited_ = false;
  loaded_model_ = file_->model;
  clear_optimization();
}

void Document::set_model(const BodyModel& model) {
  if (!loaded()) throw std::logic_error("no motion loaded");
  if (model.size() != file_->model.size())
    throw std::invalid_argument("the edited model has other segments than the motion's");
  MotionEvaluation evaluation = evaluate_motion(file_->motion, model, evaluate_options_);
  std::vector<RotationSample> rotation = rotation_metrics(model, evaluation.samples);
  file_->model = model;
  evaluation_ = std::move(evaluation);
  rotation_ = std::move(rotation);
  edited_ = true;
  clear_optimization();
}

void Document::set_motion(const Motion& motion) {
  if (!loaded()) throw std::logic_error("no motion loaded");
  MotionEvaluation evaluation = evaluate_motion(motion, file_->model, evaluate_options_);
  std::vector<RotationSample> rotation = rotation_metrics(file_->model, evaluation.samples);
  file_->motion = motion;
  evaluation_ = std::move(evaluation);
  rotation_ = std::move(rotation);
  edited_ = true;
  clear_optimization();
}

void Document::set_optimization(OptimizationResult result, const OptimizeOptions& options) {
  if (!loaded()) throw std::logic_error("no motion loaded");
  rotation_opt_before_ = rotation_metrics(file_->model, result.before.samples);
  rotation_opt_after_ = rotation_metrics(file_->model, result.after.samples);
  optimization_ = std::move(result);
  optimize_options_ = options;
}

void Document::clear_optimization() {
  optimization_.reset();
  rotation_opt_before_.clear();
  rotation_opt_after_.clear();
}

Stage Document::available(Stage wanted) const {
  return wanted == Stage::kAfter && has_optimization() ? Stage::kAfter : Stage::kBefore;
}

const MotionEvaluation& Document::evaluation(Stage stage) const {
  if (!has_optimization()) return evaluation_;
  return stage == Stage::kAfter ? optimization_->after : optimization_->before;
}

const std::vector<RotationSample>& Document::rotation(Stage stage) const {
  if (!has_optimization()) return rotation_;
  return stage == Stage::kAfter ? rotation_opt_after_ : rotation_opt_before_;
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
double typical_over_stages(const Document& d, Measure measure) {
  double typical = 0.0;
  for (Stage stage : {Stage::kBefore, Stage::kAfter}) {
    if (d.available(stage) != stage) continue;
    std::vector<double> values;
    for (const SampleRecord& s : d.evaluation(stage).samples)
      values.push_back(measure(s));
    if (values.empty()) continue;
    const std::size_t k = static_cast<std::size_t>(kScalePercentile * (values.size() - 1) + 0.5);
    std::nth_element(values.begin(), values.begin() + k, values.end());
    typical = std::max(typical, values[k]);
  }
  return typical;
}

double largest_joint_force(const SampleRecord& s) {
  double m = 0.0;
  for (std::size_t i = 1; i < s.joint_wrench.size(); ++i)
    m = std::max(m, s.joint_wrench[i].head<3>().norm());
  return m;
}
}  // namespace

GlyphScale Document::residual_force_scale(double max_length_m) const {
  return GlyphScale(
      typical_over_stages(*this, [](const SampleRecord& s) { return s.residual.head<3>().norm(); }),
      max_length_m);
}

GlyphScale Document::residual_moment_scale(double max_length_m) const {
  return GlyphScale(
      typical_over_stages(*this, [](const SampleRecord& s) { return s.residual.tail<3>().norm(); }),
      max_length_m);
}

GlyphScale Document::joint_force_scale(double max_length_m) const {
  return GlyphScale(typical_over_stages(*this, largest_joint_force), max_length_m);
}

void Document::save_result(const std::string& out_dir) const {
  if (!loaded()) throw std::logic_error("no motion loaded");
  if (has_optimization())
    write_optimization_outputs(out_dir, *file_, *optimization_, optimize_options_);
  else
    write_evaluation_outputs(out_dir, *file_, evaluation_, evaluate_options_);
}

}  // namespace saltus::gui
