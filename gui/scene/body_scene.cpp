#include "scene/body_scene.h"

#include <vtkBillboardTextActor3D.h>
#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkNew.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTextProperty.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <optional>
#include <string>

#include "core/what_if_report.h"
#include "saltus/evaluation/apparatus.h"
#include "saltus/evaluation/flight_checks.h"
#include "saltus/evaluation/residual_measures.h"
#include "scene/body_layer.h"
#include "scene/environment_layer.h"
#include "scene/glyph_layer.h"
#include "scene/path_layer.h"
#include "scene/scene_camera.h"
#include "scene/text_layer.h"

namespace saltus::gui {

namespace {

/// The whole-flight inset's corner of the view (normalized viewport: x0, y0, x1, y1).
constexpr double kInsetViewport[4] = {0.745, 0.015, 0.99, 0.40};
/// A motion capture's figure: light grey-green, beside the athlete by this share of the
/// standing body's height, to the right on the screen.
const Rgb kCaptureColour{0.72, 0.78, 0.70};
constexpr double kCaptureGapPerHeight = 0.95;
/// A what-if flight's figure (the What if panel): gold, beside the athlete on the other side from
/// a capture's.
const Rgb kWhatIfColour{0.93, 0.74, 0.30};
/// Labels above the figures, this far above the highest joint (m).
constexpr double kLabelHeight = 0.45;

/// Characters per line of the title and the legend before they wrap.
constexpr std::size_t kTitleWidth = 34;
constexpr std::size_t kLegendWidth = 64;

std::string printf_string(const char* format, ...) __attribute__((format(printf, 1, 2)));
std::string printf_string(const char* format, ...) {
  char buffer[512];
  va_list args;
  va_start(args, format);
  std::vsnprintf(buffer, sizeof buffer, format, args);
  va_end(args);
  return buffer;
}

/// The value as printed with `decimals` decimals, without the "-0.00" of tiny negatives.
double tidy(double value, int decimals) {
  const double scale = std::pow(10.0, decimals);
  const double rounded = std::round(value * scale) / scale;
  return rounded == 0.0 ? 0.0 : rounded;
}

}  // namespace

struct BodyScene::Impl {
  vtkNew<vtkRenderer> renderer;
  vtkNew<vtkRenderer> inset;    ///< the whole flight, in a corner, own camera
  vtkNew<vtkRenderer> overlay;  ///< layer 1: CoM ball and residual arrows, always visible
  scene::BodyLayer body{renderer};
  scene::BodyLayer capture_body{renderer};  ///< the motion capture beside the athlete
  vtkNew<vtkBillboardTextActor3D> capture_label;
  vtkNew<vtkBillboardTextActor3D> athlete_label;
  std::optional<SampleRecord> capture_now;  ///< the capture at the time shown
  std::optional<SampleRecord> athlete_now;  ///< the motion at the time shown
  scene::BodyLayer what_if_body{renderer};  ///< a what-if flight beside the athlete
  vtkNew<vtkBillboardTextActor3D> what_if_label;
  std::string what_if_legend;  ///< the legend's line for the gold figure
  std::vector<SampleRecord> what_if_samples;
  /// The screen boxes of the figures' labels placed in this picture, so that none covers another.
  std::vector<std::array<double, 4>> placed_labels;
  std::optional<SampleRecord> what_if_now;  ///< posed, its offset included
  scene::EnvironmentLayer environment{renderer};
  scene::PathLayer paths{renderer, overlay};
  scene::GlyphLayer glyphs{renderer, overlay};
  scene::TextLayer texts{renderer, inset};
  scene::SceneCamera camera;
  vtkNew<vtkCallbackCommand> on_resize;  ///< renderer StartEvent: fit the texts

  SceneOptions options;
  const Document* document = nullptr;
  Stage stage = Stage::kBefore;
  double time = 0.0;
  bool video = false;
  std::optional<GlyphTypicals> shared_typicals;
  double forward_sign = 1.0;              ///< +1 if a positive somersault count is forward
  double whole_flight_somersaults = 0.0;  ///< the stage's count at landing (its direction)
  std::chrono::steady_clock::time_point last_text;
  Eigen::Vector3d com = Eigen::Vector3d(0, 1, 0);
  std::optional<double> framing_height;  ///< m, else the body's own standing height

  Impl() {
    overlay->SetLayer(1);
    overlay->InteractiveOff();
    overlay->SetActiveCamera(renderer->GetActiveCamera());
    renderer->GradientBackgroundOn();
    renderer->SetBackground(0.10, 0.12, 0.16);
    renderer->SetBackground2(0.30, 0.36, 0.46);
    inset->SetViewport(kInsetViewport[0], kInsetViewport[1], kInsetViewport[2], kInsetViewport[3]);
    inset->SetBackground(0.07, 0.08, 0.11);
    inset->InteractiveOff();
    inset->GetActiveCamera()->ParallelProjectionOn();
    body.show_in(inset);
    environment.show_in(inset);
    paths.show_in(inset);
    // Before each render: text sizes for the view's height (fit does nothing if unchanged).
    on_resize->SetClientData(this);
    on_resize->SetCallback([](vtkObject* caller, unsigned long, void* self, void*) {
      const int* size = static_cast<vtkRenderer*>(caller)->GetSize();
      Impl& impl = *static_cast<Impl*>(self);
      impl.texts.fit(size[1]);
      // The user may have turned the camera: the capture stays to the right on the screen.
      if (impl.athlete_now) impl.place_beside(*impl.athlete_now);
    });
    renderer->AddObserver(vtkCommand::StartEvent, on_resize);
    for (vtkBillboardTextActor3D* label :
         {capture_label.Get(), athlete_label.Get(), what_if_label.Get()}) {
      vtkTextProperty* p = label->GetTextProperty();
      p->SetFontSize(18);
      p->SetJustificationToCentered();
      p->SetBold(true);
      p->SetColor(0.92, 0.94, 0.90);
      label->PickableOff();
      label->SetVisibility(false);
      renderer->AddActor(label);
    }
    capture_label->SetInput("capture");
  }

  bool capture_shown() const { return document && document->capture() && options.capture_figure; }
  /// A what-if flight is drawn when it has samples that fit the document's model.
  bool what_if_drawn() const {
    return document && !what_if_samples.empty() &&
           what_if_samples.front().segment_rotation.size() ==
               static_cast<std::size_t>(document->file().model.size());
  }
  /// Whether the athlete has a figure beside it, so that both are labelled.
  bool figure_beside() const { return capture_shown() || what_if_drawn(); }

  /// Where the capture's figure goes: to the right of the athlete as the camera sees it.
  Eigen::Vector3d capture_offset() const {
    vtkCamera* c = renderer->GetActiveCamera();
    double dop[3], up[3];
    c->GetDirectionOfProjection(dop);
    c->GetViewUp(up);
    Eigen::Vector3d right =
        Eigen::Vector3d(dop[0], dop[1], dop[2]).cross(Eigen::Vector3d(up[0], up[1], up[2]));
    if (right.norm() < 1e-9) right = Eigen::Vector3d::UnitX();
    return right.normalized() * kCaptureGapPerHeight * body.standing_height();
  }

  static double top_of(const SampleRecord& s) {
    double top = s.com.y();
    for (const Eigen::Vector3d& p : s.segment_position)
      top = std::max(top, p.y());
    return top;
  }

  /// Where the what-if figure goes: to the right of the athlete, or to its left when a capture
  /// is there.
  Eigen::Vector3d what_if_offset() const {
    return capture_shown() ? Eigen::Vector3d(-capture_offset()) : capture_offset();
  }

  static double bottom_of(const SampleRecord& s) {
    double bottom = s.com.y();
    for (const Eigen::Vector3d& p : s.segment_position)
      bottom = std::min(bottom, p.y());
    return bottom;
  }

  /// Puts a label above a figure posed at `sample` moved by `offset`; where that would be drawn
  /// over other words (over_words: the title of a short view, the inset, another figure's
  /// label) or cut at the view's edge, below its feet, else beside it at its CoM's height
  /// (`side`: -1 to the left on the screen, +1 to the right).
  void label_above(vtkBillboardTextActor3D* label, const SampleRecord& sample,
                   const Eigen::Vector3d& offset, int side) {
    const Eigen::Vector3d centre = sample.com + offset;
    const Eigen::Vector3d above =
        centre + Eigen::Vector3d(0, top_of(sample) - sample.com.y() + kLabelHeight, 0);
    const Eigen::Vector3d below =
        centre + Eigen::Vector3d(0, bottom_of(sample) - sample.com.y() - 0.5 * kLabelHeight, 0);
    std::vector<Eigen::Vector3d> places = {above, below};
    if (const std::optional<Eigen::Vector3d> beside = beside_on_screen(label, centre, side))
      places.push_back(*beside);
    Eigen::Vector3d chosen = above;
    for (const Eigen::Vector3d& at : places)
      if (!over_words(label, at)) {
        chosen = at;
        break;
      }
    label->SetPosition(chosen.x(), chosen.y(), chosen.z());
    if (const std::optional<std::array<double, 4>> box = label_box(label, chosen))
      placed_labels.push_back(*box);
  }

  /// The world point a label's width away from `at` on the screen, to the `side`, at its depth.
  std::optional<Eigen::Vector3d> beside_on_screen(vtkBillboardTextActor3D* label,
                                                  const Eigen::Vector3d& at, int side) {
    const int* size = renderer->GetSize();
    if (size[0] <= 0 || size[1] <= 0) return std::nullopt;
    renderer->SetWorldPoint(at.x(), at.y(), at.z(), 1.0);
    renderer->WorldToDisplay();
    double p[3];
    renderer->GetDisplayPoint(p);
    const double font = label->GetTextProperty()->GetFontSize();
    const double width = 0.64 * font * std::strlen(label->GetInput() ? label->GetInput() : "");
    renderer->SetDisplayPoint(p[0] + side * (0.5 * width + 0.06 * size[0]), p[1], p[2]);
    renderer->DisplayToWorld();
    const double* w = renderer->GetWorldPoint();
    if (!(std::abs(w[3]) > 0.0)) return std::nullopt;
    return Eigen::Vector3d(w[0] / w[3], w[1] / w[3], w[2] / w[3]);
  }

  /// Whether a label at `at` (world) would be drawn over the title, the numbers or the legend.
  /// A label's box on the screen at `at` (x0, x1, y0, y1): centred on the point, its text as wide
  /// as its characters; nullopt before the view has a size.
  std::optional<std::array<double, 4>> label_box(vtkBillboardTextActor3D* label,
                                                 const Eigen::Vector3d& at) {
    const int* size = renderer->GetSize();
    if (size[0] <= 0 || size[1] <= 0) return std::nullopt;
    renderer->SetWorldPoint(at.x(), at.y(), at.z(), 1.0);
    renderer->WorldToDisplay();
    const double* p = renderer->GetDisplayPoint();
    const double font = label->GetTextProperty()->GetFontSize();
    const double half_width = 0.32 * font * std::strlen(label->GetInput() ? label->GetInput() : "");
    return std::array<double, 4>{p[0] - half_width, p[0] + half_width, p[1] - 0.2 * font,
                                 p[1] + 1.2 * font};
  }

  /// Whether a label at `at` would be cut at the view's edge or cover the words in its corners,
  /// the whole-flight inset or a figure's label placed before it in this picture.
  bool over_words(vtkBillboardTextActor3D* label, const Eigen::Vector3d& at) {
    const std::optional<std::array<double, 4>> box = label_box(label, at);
    if (!box) return false;
    const auto overlaps = [&](const std::array<double, 4>& other) {
      return (*box)[0] < other[1] && other[0] < (*box)[1] && (*box)[2] < other[3] &&
             other[2] < (*box)[3];
    };
    const int* size = renderer->GetSize();
    if ((*box)[0] < 0 || (*box)[1] > size[0] || (*box)[2] < 0 || (*box)[3] > size[1])
      return true;  // cut at the view's edge
    for (const std::array<double, 4>& words : texts.boxes(renderer))
      if (overlaps(words)) return true;
    for (const std::array<double, 4>& placed : placed_labels)
      if (overlaps(placed)) return true;
    if (inset->GetDraw()) {  // the whole-flight inset, drawn over its corner of the view
      const std::array<double, 4> corner{kInsetViewport[0] * size[0], kInsetViewport[2] * size[0],
                                         kInsetViewport[1] * size[1], kInsetViewport[3] * size[1]};
      if (overlaps(corner)) return true;
    }
    return false;
  }

  /// Poses the figures beside the athlete, the capture's and the what-if flight's (again after
  /// the camera turned), and labels them.
  void place_beside(const SampleRecord& athlete) {
    placed_labels.clear();
    if (capture_shown() && capture_now) {
      capture_body.pose(*capture_now, capture_offset());
      label_above(capture_label, *capture_now, capture_offset(), +1);
    }
    what_if_now.reset();
    if (what_if_drawn()) {
      const Eigen::Vector3d offset = what_if_offset();
      SampleRecord s = flight_sample_at(what_if_samples, time);
      what_if_body.pose(s, offset);
      label_above(what_if_label, s, offset, capture_shown() ? -1 : +1);
      for (Eigen::Vector3d& p : s.segment_position)
        p += offset;
      s.com += offset;
      what_if_now = s;
    }
    if (figure_beside()) label_above(athlete_label, athlete, Eigen::Vector3d::Zero(), -1);
  }

  void clear() {
    body.clear();
    capture_body.clear();
    capture_now.reset();
    what_if_body.clear();
    what_if_now.reset();
    athlete_now.reset();
    environment.clear();
    paths.clear();
    glyphs.clear();
  }

  void build(const Document& d) {
    const MotionFile& file = d.file();
    body.build(file.model);
    if (d.capture()) capture_body.build(file.model, kCaptureColour);
    what_if_body.build(file.model, kWhatIfColour);
    athlete_label->SetInput(stage == Stage::kAfter || file.motion.spline ? "optimised"
                                                                         : "keyframes");
    paths.build(d, stage);
    const std::vector<SampleRecord>& samples = d.plot_samples(stage);
    const Apparatus apparatus = apparatus_for(file.model, file.motion.takeoff, samples);
    environment.build(apparatus, paths.flight_bounds());
    body.build_ghosts(file.model, d.keyframe_poses(stage), stage == Stage::kAfter);
    glyphs.build(file.model.size());
    glyphs.set_scales(shared_typicals ? *shared_typicals : d.arrow_typicals());
    forward_sign = samples.empty() ? 1.0 : forward_somersault_sign(samples.front());
    const std::vector<RotationSample>& turns = d.rotation(stage);
    whole_flight_somersaults = turns.empty() ? 0.0 : turns.back().somersaults;
    // The cameras look at the athlete from its own take-off axes.
    Eigen::Vector3d forward =
        samples.empty() ? Eigen::Vector3d::UnitZ()
                        : samples.front().segment_rotation.front() * Eigen::Vector3d::UnitZ();
    forward.y() = 0.0;
    if (forward.norm() < 1e-6) forward = Eigen::Vector3d::UnitZ();
    forward.normalize();
    const Eigen::Vector3d left = Eigen::Vector3d::UnitY().cross(forward);
    camera.set_athlete(forward, left, framing_height ? *framing_height : body.standing_height());
    fit_inset(left);
  }

  /// The inset's camera: from the athlete's right, the whole flight and the apparatus near it.
  void fit_inset(const Eigen::Vector3d& left) {
    Eigen::AlignedBox3d box = environment.frame_bounds();
    box.extend(paths.flight_bounds());
    const Eigen::Vector3d centre = box.center();
    const Eigen::Vector3d position = centre - 30.0 * left;
    vtkCamera* c = inset->GetActiveCamera();
    c->SetFocalPoint(centre.x(), centre.y(), centre.z());
    c->SetPosition(position.x(), position.y(), position.z());
    c->SetViewUp(0, 1, 0);
    // A margin of a body's reach around the flight.
    const double b[6] = {box.min().x() - 1.0, box.max().x() + 1.0, box.min().y() - 0.5,
                         box.max().y() + 1.2, box.min().z() - 1.0, box.max().z() + 1.0};
    inset->ResetCamera(b);
    c->SetParallelScale(0.5 * (b[3] - b[2]) * 1.05);
  }

  void apply_visibility() {
    const bool has_doc = document != nullptr;
    environment.set_visible(options.apparatus, options.floor_grid);
    paths.set_visible(options.parabola, options.com_trace, has_doc);
    body.set_ghosts_visible(options.ghosts);
    capture_body.set_visible(capture_shown());
    capture_label->SetVisibility(capture_shown());
    what_if_body.set_visible(what_if_drawn());
    what_if_label->SetVisibility(what_if_drawn());
    athlete_label->SetVisibility(figure_beside());
    if (!has_doc) glyphs.hide();
    const bool inset_shown = has_doc && options.flight_inset;
    inset->SetDraw(inset_shown);
    texts.set_visible(true, has_doc && options.physics_text && !video,
                      has_doc && !video && (options.residual_arrows || options.joint_arrows),
                      has_doc && video, inset_shown);
  }

  /// "1 m = 50 N" kept on one line when the legend wraps (no-break spaces).
  static std::string unbroken(std::string text) {
    std::string out;
    for (char c : text)
      out += c == ' ' ? std::string("\u00a0") : std::string(1, c);
    return out;
  }

  std::string legend_text() const {
    // Say that the scale stays: a small arrow after optimisation is a small residual.
    std::string arrows = "Arrows at the yellow CoM: force " +
                         unbroken(glyphs.force_scale().legend("N")) + ", moment (two heads) " +
                         unbroken(glyphs.moment_scale().legend("N·m")) +
                         (shared_typicals ? "; one scale in both views"
                                          : "; one scale before and after optimisation") +
                         "; green small, red full scale.";
    if (options.joint_arrows)
      arrows += " At the joints: joint forces, " + unbroken(glyphs.joint_scale().legend("N")) + ".";
    // As many characters a line as the view's width holds at the legend's text size.
    const int* size = renderer->GetSize();
    const std::size_t width =
        size[0] > 0
            ? std::clamp<std::size_t>(static_cast<std::size_t>(size[0] / 9), 30, kLegendWidth)
            : kLegendWidth;
    std::string text = scene::wrapped(arrows, width);
    text += "\nLines: white = ballistic parabola, orange = this motion's CoM path";
    if (options.ghosts) text += "\nPale thin figures: the keyframe poses";
    if (capture_shown())
      text += "\nGrey figure: the motion capture itself (its residual: the grey-green curves)";
    if (what_if_drawn()) text += "\nGold figure: " + what_if_legend;
    return text;
  }

  void update_time(bool playing = false) {
    if (!document) return;
    const SampleRecord s = document->sample_at(stage, time);
    com = s.com;
    body.pose(s);
    paths.set_com(s.com);
    glyphs.update(s, options.residual_arrows, options.joint_arrows);
    athlete_now = s;
    if (capture_shown()) capture_now = document->capture_sample_at(time);
    place_beside(s);
    camera.follow(renderer->GetActiveCamera(), focus(s.com));
    // The overlay shares this camera and so its clipping range, which covers its props too.
    renderer->ResetCameraClippingRange();

    const auto now = std::chrono::steady_clock::now();
    if (playing && now - last_text < std::chrono::duration<double>(1.0 / kTextRefreshPerSecond))
      return;
    last_text = now;
    update_texts(s);
  }

  void update_texts(const SampleRecord& s) {
    const MotionFile& file = document->file();
    const double force = s.residual.head<3>().norm();
    const double moment = s.residual.tail<3>().norm();
    const double percent = percent_of_body_weight(force, file.model);
    // A motion file with a stored spline (optimized.motion.json) is an optimised result: its
    // "before" is that trajectory as saved, not an interpolation of its keyframes.
    const char* shown = stage == Stage::kAfter ? "optimised motion (after)"
                        : file.motion.spline   ? "optimised trajectory, as saved"
                                               : "interpolated keyframes (before optimisation)";
    texts.set_title(scene::wrapped(file.motion.name, kTitleWidth) + "\n" + shown +
                    printf_string("\nt = %.3f s of %.3f s", time, document->duration()));
    if (video) {
      // The time is in the title; the residual here, short enough for a small video.
      texts.set_banner(printf_string("residual |F| %.1f N\n(%.1f %% of body weight)\n|M| %.1f N·m",
                                     force, percent, moment));
      return;
    }
    const RotationSample r = document->rotation_at(stage, time);
    const double somersaults = forward_sign * r.somersaults;
    texts.set_numbers(
        printf_string("Residual |F| %.1f N (%.1f %% of body weight), |M| %.1f N·m\n", force,
                      percent, moment) +
        printf_string("Spin %.2f rad/s, inertia I_xx %.2f kg·m², |L| %.1f kg·m²/s\n",
                      tidy(std::abs(r.somersault_rate), 2), r.somersault_inertia,
                      r.angular_momentum.norm()) +
        printf_string(
            "%.2f somersaults %s, %.2f twists", tidy(std::abs(somersaults), 2),
            somersault_direction(somersaults, forward_sign * whole_flight_somersaults).c_str(),
            tidy(std::abs(r.twists), 2)));
    texts.set_legend(legend_text());
  }

  /// What the camera follows: the athlete's CoM, or with figures beside it the middle of them
  /// all.
  Eigen::Vector3d focus(const Eigen::Vector3d& athlete_com) const {
    Eigen::Vector3d sum = athlete_com;
    int count = 1;
    if (capture_shown()) {
      sum += athlete_com + capture_offset();
      ++count;
    }
    if (what_if_drawn()) {
      sum += athlete_com + what_if_offset();
      ++count;
    }
    return sum / count;
  }

  void apply_camera() {
    camera.reset(renderer->GetActiveCamera(), com);
    camera.follow(renderer->GetActiveCamera(), focus(com));
    renderer->ResetCameraClippingRange();
  }
};

BodyScene::BodyScene() : impl_(std::make_unique<Impl>()) {
  impl_->texts.set_title("Open a motion file (File > Open, or drop a *.motion.json here)");
  impl_->apply_visibility();
  impl_->apply_camera();
}

BodyScene::~BodyScene() = default;

void BodyScene::attach(vtkRenderWindow* window) {
  window->SetNumberOfLayers(2);
  window->AddRenderer(impl_->renderer);
  window->AddRenderer(impl_->inset);  // after the scene in layer 0: drawn over its corner
  window->AddRenderer(impl_->overlay);
}

void BodyScene::set_framing_height(std::optional<double> height) {
  impl_->framing_height = height;
}

void BodyScene::set_document(const Document* document, Stage stage) {
  Impl& d = *impl_;
  d.clear();
  d.document = document && document->loaded() ? document : nullptr;
  if (!d.document) {
    d.texts.set_title("Open a motion file (File > Open, or drop a *.motion.json here)");
    d.apply_visibility();
    return;
  }
  d.stage = document->available(stage);
  d.build(*document);
  d.body.set_highlight(d.body.highlight());
  d.time = std::clamp(d.time, 0.0, document->duration());
  d.apply_visibility();
  d.update_time();
}

void BodyScene::set_options(const SceneOptions& options) {
  impl_->options = options;
  impl_->apply_visibility();
  impl_->update_time();
}

const SceneOptions& BodyScene::options() const {
  return impl_->options;
}

void BodyScene::set_time(double t, bool playing) {
  impl_->time = t;
  impl_->update_time(playing);
}

double BodyScene::time() const {
  return impl_->time;
}

void BodyScene::set_camera(CameraPreset preset) {
  impl_->camera.set_preset(preset);
  impl_->apply_camera();
}

CameraPreset BodyScene::camera() const {
  return impl_->camera.preset();
}

void BodyScene::reset_camera() {
  impl_->apply_camera();
}

void BodyScene::set_glyph_typicals(std::optional<GlyphTypicals> typicals) {
  Impl& d = *impl_;
  d.shared_typicals = typicals;
  if (!d.document) return;
  d.glyphs.set_scales(typicals ? *typicals : d.document->arrow_typicals());
  d.update_time();
}

double BodyScene::residual_force_arrow_length() const {
  return impl_->document ? impl_->glyphs.force_length() : 0.0;
}

double BodyScene::residual_force_full_scale() const {
  return impl_->glyphs.force_scale().full_scale();
}

void BodyScene::set_what_if(std::vector<SampleRecord> samples, const std::string& label,
                            const std::string& legend) {
  Impl& d = *impl_;
  d.what_if_samples = std::move(samples);
  d.what_if_legend = legend;
  d.what_if_label->SetInput(label.c_str());
  d.apply_visibility();
  d.update_time();
}

bool BodyScene::what_if_shown() const {
  return impl_->what_if_drawn();
}

std::optional<SampleRecord> BodyScene::what_if_pose() const {
  return impl_->what_if_now;
}

std::string BodyScene::legend() const {
  return impl_->document ? impl_->legend_text() : std::string();
}

std::string BodyScene::title() const {
  return impl_->texts.title();
}

void BodyScene::set_antialiasing(bool on) {
  impl_->renderer->SetUseFXAA(on);
}

bool BodyScene::antialiasing() const {
  return impl_->renderer->GetUseFXAA();
}

void BodyScene::set_video_overlay(bool on) {
  impl_->video = on;
  impl_->apply_visibility();
  impl_->update_time();
}

int BodyScene::segment_at(int x, int y) const {
  Impl& d = *impl_;
  if (!d.document) return -1;
  // A click on the inset is not a click on the body behind it.
  if (d.inset->GetDraw() && d.inset->IsInViewport(x, y)) return -1;
  return d.body.segment_at(x, y);
}

void BodyScene::set_highlight(int segment) {
  impl_->body.set_highlight(segment);
  impl_->update_time();
}

int BodyScene::highlight() const {
  return impl_->body.highlight();
}

}  // namespace saltus::gui
