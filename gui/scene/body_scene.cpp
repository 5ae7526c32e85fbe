#include "scene/body_scene.h"

#include <vtkActor.h>
#include <vtkAppendPolyData.h>
#include <vtkArrowSource.h>
#include <vtkCamera.h>
#include <vtkCapsuleSource.h>
#include <vtkCellArray.h>
#include <vtkCellPicker.h>
#include <vtkConeSource.h>
#include <vtkCoordinate.h>
#include <vtkCubeSource.h>
#include <vtkLookupTable.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkPlaneSource.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyLine.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkSmartPointer.h>
#include <vtkSphereSource.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkTransform.h>
#include <vtkTransformPolyDataFilter.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <string>
#include <vector>

#include "scene/vtk_text.h"

namespace saltus::gui {

namespace {

// Trampoline dimensions (FIG apparatus norms): bed 4.28 m × 2.14 m, frame with pads 5.05 × 2.91.
// The athlete faces +z, along the bed's long side.
constexpr double kBedLength = 4.28, kBedWidth = 2.14;
constexpr double kFrameLength = 5.05, kFrameWidth = 2.91;
constexpr double kArrowMaxLength = 1.0;       ///< m, full-scale residual arrows
constexpr double kJointArrowMaxLength = 0.5;  ///< m, full-scale joint-force arrows
constexpr double kFollowDistance = 7.0;       ///< m, camera to CoM in follow mode
constexpr double kGhostRadiusFactor = 0.35;   ///< keyframe poses drawn as thin figures
/// The picked segment: its colour this far towards white, and an outline this much wider (a
/// share of its radius, at least kOutlineMinWidth) drawn only where it sticks out behind it.
constexpr double kHighlightWhiten = 0.4;
constexpr double kOutlineWidthFactor = 0.3;
constexpr double kOutlineMinWidth = 0.015;  ///< m

const Rgb kLeftColour{0.25, 0.47, 0.88};
const Rgb kRightColour{0.93, 0.45, 0.18};
const Rgb kTrunkColour{0.86, 0.82, 0.74};
const Rgb kParabolaColour{0.92, 0.92, 0.95};
const Rgb kTraceColour{1.0, 0.70, 0.20};
/// Pale cyan: no other part of the scene has it (sides blue and orange, arrows green to red).
const Rgb kOutlineColour{0.45, 0.95, 1.0};

enum class Side { kLeft, kRight, kCentre };

Side side_of(const std::string& name) {
  if (name.size() > 2 && name.compare(name.size() - 2, 2, "_l") == 0) return Side::kLeft;
  if (name.size() > 2 && name.compare(name.size() - 2, 2, "_r") == 0) return Side::kRight;
  return Side::kCentre;
}

void set_colour(vtkActor* actor, const Rgb& c) {
  actor->GetProperty()->SetColor(c.r, c.g, c.b);
}

void set_matrix(vtkActor* actor, const Eigen::Affine3d& transform) {
  vtkNew<vtkMatrix4x4> m;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c)
      m->SetElement(r, c, transform.matrix()(r, c));
  actor->SetUserMatrix(m);
}

vtkSmartPointer<vtkActor> actor_for(vtkPolyDataMapper* mapper) {
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  return actor;
}

vtkSmartPointer<vtkPolyDataMapper> mapper_for(vtkAlgorithmOutput* port) {
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputConnection(port);
  return mapper;
}

vtkSmartPointer<vtkPolyData> polyline(const std::vector<Eigen::Vector3d>& points) {
  vtkNew<vtkPoints> pts;
  vtkNew<vtkPolyLine> line;
  line->GetPointIds()->SetNumberOfIds(static_cast<vtkIdType>(points.size()));
  for (std::size_t i = 0; i < points.size(); ++i) {
    pts->InsertNextPoint(points[i].x(), points[i].y(), points[i].z());
    line->GetPointIds()->SetId(static_cast<vtkIdType>(i), static_cast<vtkIdType>(i));
  }
  vtkNew<vtkCellArray> cells;
  cells->InsertNextCell(line);
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(pts);
  data->SetLines(cells);
  return data;
}

/// Arrow of the given length along `direction` from `origin`; the unit glyph points along +x.
/// Thickness shrinks with very short arrows so that a tiny residual looks tiny.
Eigen::Affine3d arrow_transform(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                                double length, double thickness) {
  const Eigen::Quaterniond turn =
      Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitX(), direction.normalized());
  const double w = thickness * std::min(1.0, length / 0.25);
  Eigen::Affine3d t = Eigen::Affine3d::Identity();
  t.translate(origin);
  t.rotate(turn);
  t.scale(Eigen::Vector3d(length, w, w));
  return t;
}

vtkSmartPointer<vtkLookupTable> magnitude_table(double full_scale) {
  auto table = vtkSmartPointer<vtkLookupTable>::New();
  const int n = 64;
  table->SetNumberOfTableValues(n);
  for (int i = 0; i < n; ++i) {
    const Rgb c = magnitude_colour(static_cast<double>(i) / (n - 1));
    table->SetTableValue(i, c.r, c.g, c.b, 1.0);
  }
  table->SetRange(0.0, full_scale);
  table->Build();
  return table;
}

vtkSmartPointer<vtkTextActor> text_actor(double x, double y, int horizontal, int vertical,
                                         int size) {
  auto actor = vtkSmartPointer<vtkTextActor>::New();
  actor->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  actor->GetPositionCoordinate()->SetValue(x, y);
  vtkTextProperty* p = actor->GetTextProperty();
  apply_font(p, size, 0.95, 0.95, 0.97);
  p->SetJustification(horizontal);
  p->SetVerticalJustification(vertical);
  p->SetLineSpacing(1.15);
  return actor;
}

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
  vtkNew<vtkRenderer> overlay;  ///< layer 1: CoM marker and residual arrows, always visible
  SceneOptions options;
  CameraPreset preset = CameraPreset::kSide;
  const Document* document = nullptr;
  Stage stage = Stage::kBefore;
  double time = 0.0;
  std::chrono::steady_clock::time_point last_text;
  Eigen::Vector3d current_com = Eigen::Vector3d(0, 1, 0);

  // Body.
  std::vector<vtkSmartPointer<vtkPolyDataMapper>> segment_mappers;
  std::vector<vtkSmartPointer<vtkActor>> segments;
  std::vector<double> segment_offset;  ///< capsule centre along the segment's y axis
  std::vector<Rgb> segment_colour;
  std::vector<Eigen::Vector3d> outline_scale;  ///< capsule to its outline, per axis
  vtkSmartPointer<vtkActor> face;              ///< marks where the athlete faces
  int face_segment = 0;
  Eigen::Vector3d face_offset = Eigen::Vector3d::Zero();
  vtkSmartPointer<vtkActor> ghosts;  ///< every keyframe pose, one mesh
  vtkNew<vtkCellPicker> picker;      ///< picks among the segments (and the face) only
  int highlight = -1;
  /// The highlighted segment's capsule, enlarged, with its front faces culled: only a rim
  /// around the segment shows.
  vtkNew<vtkActor> outline;

  // Environment.
  std::vector<vtkSmartPointer<vtkActor>> trampoline;
  vtkSmartPointer<vtkActor> grid;
  vtkSmartPointer<vtkActor> parabola;
  vtkSmartPointer<vtkActor> trace;
  vtkSmartPointer<vtkActor> com_marker;

  // Glyphs.
  vtkSmartPointer<vtkPolyDataMapper> arrow_mapper;
  vtkSmartPointer<vtkPolyDataMapper> double_arrow_mapper;
  vtkSmartPointer<vtkActor> force_arrow;
  vtkSmartPointer<vtkActor> moment_arrow;
  std::vector<vtkSmartPointer<vtkActor>> joint_arrows;
  GlyphScale force_scale, moment_scale, joint_scale;
  vtkSmartPointer<vtkScalarBarActor> force_bar, moment_bar;

  // Texts.
  vtkSmartPointer<vtkTextActor> title, physics, legend;

  // Flight bounds for fitting the camera.
  double bounds[6] = {-2, 2, 0, 3, -3, 3};

  Impl() {
    overlay->SetLayer(1);
    overlay->InteractiveOff();
    overlay->SetActiveCamera(renderer->GetActiveCamera());
    renderer->GradientBackgroundOn();
    renderer->SetBackground(0.10, 0.12, 0.16);
    renderer->SetBackground2(0.30, 0.36, 0.46);

    vtkNew<vtkArrowSource> arrow;
    arrow->SetTipLength(0.25);
    arrow->SetTipRadius(0.08);
    arrow->SetShaftRadius(0.025);
    arrow->SetTipResolution(16);
    arrow->SetShaftResolution(12);
    arrow_mapper = mapper_for(arrow->GetOutputPort());
    vtkNew<vtkConeSource> second_head;
    second_head->SetHeight(0.25);
    second_head->SetRadius(0.08);
    second_head->SetResolution(16);
    second_head->SetDirection(1, 0, 0);
    second_head->SetCenter(0.625, 0, 0);
    vtkNew<vtkAppendPolyData> both;
    both->AddInputConnection(arrow->GetOutputPort());
    both->AddInputConnection(second_head->GetOutputPort());
    double_arrow_mapper = mapper_for(both->GetOutputPort());

    force_arrow = actor_for(arrow_mapper);
    moment_arrow = actor_for(double_arrow_mapper);
    for (vtkActor* a : {force_arrow.Get(), moment_arrow.Get()}) {
      a->GetProperty()->SetSpecular(0.3);
      overlay->AddActor(a);
    }

    vtkNew<vtkSphereSource> sphere;
    sphere->SetRadius(0.07);
    sphere->SetThetaResolution(16);
    sphere->SetPhiResolution(12);
    com_marker = actor_for(mapper_for(sphere->GetOutputPort()));
    set_colour(com_marker, {1.0, 0.90, 0.25});
    com_marker->GetProperty()->SetAmbient(0.4);
    overlay->AddActor(com_marker);

    build_environment();

    picker->PickFromListOn();
    outline->GetProperty()->FrontfaceCullingOn();
    outline->GetProperty()->SetLighting(false);
    set_colour(outline, kOutlineColour);
    outline->PickableOff();
    outline->SetVisibility(false);
    renderer->AddActor(outline);

    force_bar = vtkSmartPointer<vtkScalarBarActor>::New();
    moment_bar = vtkSmartPointer<vtkScalarBarActor>::New();
    // Bottom right, one above the other: colour keys of the arrows' magnitudes.
    double y = 0.115;
    for (vtkScalarBarActor* bar : {force_bar.Get(), moment_bar.Get()}) {
      bar->SetOrientationToHorizontal();
      bar->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
      bar->GetPositionCoordinate()->SetValue(0.72, y);
      bar->SetWidth(0.27);
      bar->SetHeight(0.1);
      bar->SetNumberOfLabels(3);
      bar->SetLabelFormat("%g");
      bar->SetBarRatio(0.3);
      bar->UnconstrainedFontSizeOn();
      apply_font(bar->GetTitleTextProperty(), 13, 0.95, 0.95, 0.97);
      apply_font(bar->GetLabelTextProperty(), 12, 0.95, 0.95, 0.97);
      renderer->AddActor2D(bar);
      y -= 0.105;
    }

    title = text_actor(0.01, 0.985, VTK_TEXT_LEFT, VTK_TEXT_TOP, 16);
    physics = text_actor(0.99, 0.985, VTK_TEXT_RIGHT, VTK_TEXT_TOP, 14);
    legend = text_actor(0.01, 0.015, VTK_TEXT_LEFT, VTK_TEXT_BOTTOM, 13);
    apply_font(title->GetTextProperty(), 16, 1.0, 1.0, 1.0, true);
    title->GetTextProperty()->SetJustification(VTK_TEXT_LEFT);
    title->GetTextProperty()->SetVerticalJustification(VTK_TEXT_TOP);
    for (vtkTextActor* t : {title.Get(), physics.Get(), legend.Get()})
      renderer->AddActor2D(t);
  }

  void build_environment() {
    // Frame with pads (blue) and the bed (dark webbing) with its top at y = 0, where the feet
    // are at take-off.
    vtkNew<vtkCubeSource> frame;
    frame->SetXLength(kFrameWidth);
    frame->SetYLength(0.06);
    frame->SetZLength(kFrameLength);
    frame->SetCenter(0, -0.045, 0);
    vtkNew<vtkCubeSource> bed;
    bed->SetXLength(kBedWidth);
    bed->SetYLength(0.02);
    bed->SetZLength(kBedLength);
    bed->SetCenter(0, -0.01, 0);
    auto frame_actor = actor_for(mapper_for(frame->GetOutputPort()));
    set_colour(frame_actor, {0.16, 0.33, 0.72});
    auto bed_actor = actor_for(mapper_for(bed->GetOutputPort()));
    set_colour(bed_actor, {0.08, 0.08, 0.10});
    trampoline = {frame_actor, bed_actor};
    for (auto& a : trampoline)
      renderer->AddActor(a);

    vtkNew<vtkPlaneSource> plane;
    plane->SetOrigin(-6, -0.08, -6);
    plane->SetPoint1(6, -0.08, -6);
    plane->SetPoint2(-6, -0.08, 6);
    plane->SetResolution(12, 12);
    grid = actor_for(mapper_for(plane->GetOutputPort()));
    grid->GetProperty()->SetRepresentationToWireframe();
    grid->GetProperty()->SetLighting(false);
    set_colour(grid, {0.55, 0.58, 0.62});
    renderer->AddActor(grid);
  }

  void clear_body() {
    for (auto& a : segments)
      renderer->RemoveActor(a);
    if (ghosts) renderer->RemoveActor(ghosts);
    for (auto& a : joint_arrows)
      renderer->RemoveActor(a);
    if (face) renderer->RemoveActor(face);
    if (parabola) renderer->RemoveActor(parabola);
    if (trace) renderer->RemoveActor(trace);
    segments.clear();
    segment_mappers.clear();
    segment_offset.clear();
    segment_colour.clear();
    outline_scale.clear();
    picker->InitializePickList();
    outline->SetMapper(nullptr);
    outline->SetVisibility(false);
    ghosts = nullptr;
    joint_arrows.clear();
    face = nullptr;
    parabola = nullptr;
    trace = nullptr;
  }

  void build_body(const BodyModel& model) {
    for (const Segment& s : model.segments) {
      vtkNew<vtkCapsuleSource> capsule;
      // Cylinder from joint to joint, caps centred on the joints so neighbours overlap smoothly.
      capsule->SetRadius(std::max(s.shape.radius, 0.01));
      capsule->SetCylinderLength(std::abs(s.shape.length));
      capsule->SetThetaResolution(14);
      capsule->SetPhiResolution(8);
      auto mapper = mapper_for(capsule->GetOutputPort());
      segment_mappers.push_back(mapper);
      segment_offset.push_back(0.5 * s.shape.length);
      // The outline is the capsule grown by a constant width all round: radius r + w, and
      // half-height (cylinder half + cap) h + w.
      const double r = std::max(s.shape.radius, 0.01);
      const double h = 0.5 * std::abs(s.shape.length) + r;
      const double w = std::max(kOutlineMinWidth, kOutlineWidthFactor * r);
      outline_scale.emplace_back((r + w) / r, (h + w) / h, (r + w) / r);
      auto actor = actor_for(mapper);
      const Side side = side_of(s.name);
      segment_colour.push_back(side == Side::kLeft    ? kLeftColour
                               : side == Side::kRight ? kRightColour
                                                      : kTrunkColour);
      set_colour(actor, segment_colour.back());
      actor->GetProperty()->SetSpecular(0.25);
      actor->GetProperty()->SetSpecularPower(20);
      segments.push_back(actor);
      renderer->AddActor(actor);
      picker->AddPickList(actor);
    }
    // A small dark "nose" at the front of the top of the thorax (or the root) shows which way
    // the athlete faces: the model itself is left-right and front-back symmetric in shape.
    face_segment = std::max(0, model.segment_index("thorax"));
    const Segment& top = model.segments[face_segment];
    face_offset = Eigen::Vector3d(0, top.shape.length * 0.85, top.shape.radius * 0.9);
    vtkNew<vtkSphereSource> nose;
    nose->SetRadius(0.05);
    nose->SetThetaResolution(12);
    nose->SetPhiResolution(8);
    face = actor_for(mapper_for(nose->GetOutputPort()));
    set_colour(face, {0.75, 0.10, 0.15});
    renderer->AddActor(face);
    picker->AddPickList(face);

    for (int i = 1; i < model.size(); ++i) {
      auto a = actor_for(arrow_mapper);
      renderer->AddActor(a);
      joint_arrows.push_back(a);
    }
  }

  /// World from capsule (centred at its origin, along y) of segment i in sample s.
  Eigen::Affine3d capsule_pose(const SampleRecord& s, std::size_t i) const {
    Eigen::Affine3d t = Eigen::Affine3d::Identity();
    t.translate(s.segment_position[i]);
    t.rotate(s.segment_rotation[i]);
    t.translate(Eigen::Vector3d(0, segment_offset[i], 0));
    return t;
  }

  void pose(const SampleRecord& s) {
    for (std::size_t i = 0; i < segments.size() && i < s.segment_position.size(); ++i)
      set_matrix(segments[i], capsule_pose(s, i));
    if (highlight >= 0 && static_cast<std::size_t>(highlight) < s.segment_position.size()) {
      const auto i = static_cast<std::size_t>(highlight);
      Eigen::Affine3d t = capsule_pose(s, i);
      t.scale(outline_scale[i]);
      set_matrix(outline, t);
    }
  }

  void apply_highlight() {
    if (highlight >= static_cast<int>(segments.size())) highlight = -1;
    for (std::size_t i = 0; i < segments.size(); ++i) {
      Rgb c = segment_colour[i];
      if (static_cast<int>(i) == highlight) {
        c = {c.r + kHighlightWhiten * (1.0 - c.r), c.g + kHighlightWhiten * (1.0 - c.g),
             c.b + kHighlightWhiten * (1.0 - c.b)};
      }
      set_colour(segments[i], c);
    }
    outline->SetMapper(highlight >= 0 ? segment_mappers[static_cast<std::size_t>(highlight)]
                                      : nullptr);
    outline->SetVisibility(highlight >= 0);
  }

  void build_paths(const Document& d) {
    const ParabolaSamples p = d.parabola(240);
    parabola = vtkSmartPointer<vtkActor>::New();
    vtkNew<vtkPolyDataMapper> parabola_mapper;
    parabola_mapper->SetInputData(polyline(p.points));
    parabola->SetMapper(parabola_mapper);
    set_colour(parabola, kParabolaColour);
    parabola->GetProperty()->SetLineWidth(2.0f);
    parabola->GetProperty()->SetLighting(false);
    renderer->AddActor(parabola);

    std::vector<Eigen::Vector3d> com;
    for (const SampleRecord& s : d.evaluation(stage).samples)
      com.push_back(s.com);
    trace = vtkSmartPointer<vtkActor>::New();
    vtkNew<vtkPolyDataMapper> trace_mapper;
    trace_mapper->SetInputData(polyline(com));
    trace->SetMapper(trace_mapper);
    set_colour(trace, kTraceColour);
    trace->GetProperty()->SetLineWidth(3.5f);
    trace->GetProperty()->SetLighting(false);
    renderer->AddActor(trace);

    // Camera bounds: the flight with a body's reach around it, and the trampoline.
    double b[6] = {-kFrameWidth / 2,  kFrameWidth / 2, -0.1, 2.0,
                   -kFrameLength / 2, kFrameLength / 2};
    for (const Eigen::Vector3d& q : p.points) {
      for (int k = 0; k < 3; ++k) {
        b[2 * k] = std::min(b[2 * k], q[k] - 1.1);
        b[2 * k + 1] = std::max(b[2 * k + 1], q[k] + 1.1);
      }
    }
    std::copy(b, b + 6, bounds);
  }

  void build_ghosts(const Document& d) {
    // Before: pale blue-grey; after (poses at the optimised times): pale amber.
    const Rgb colour = stage == Stage::kAfter ? Rgb{0.80, 0.70, 0.52} : Rgb{0.70, 0.76, 0.86};
    // All keyframe poses in one mesh and one actor: they never move, and one draw call instead
    // of one per segment and pose keeps software OpenGL near the frame rate without them.
    vtkNew<vtkAppendPolyData> all;
    for (const SampleRecord& pose_at_key : d.keyframe_poses(stage)) {
      for (std::size_t i = 0; i < segment_mappers.size(); ++i) {
        Eigen::Affine3d t = Eigen::Affine3d::Identity();
        t.translate(pose_at_key.segment_position[i]);
        t.rotate(pose_at_key.segment_rotation[i]);
        t.translate(Eigen::Vector3d(0, segment_offset[i], 0));
        vtkNew<vtkTransform> transform;
        vtkNew<vtkMatrix4x4> m;
        for (int r = 0; r < 4; ++r)
          for (int c = 0; c < 4; ++c)
            m->SetElement(r, c, t.matrix()(r, c));
        transform->SetMatrix(m);
        // Thin (a third of the radius) so that a pose next to the body does not hide it.
        vtkNew<vtkCapsuleSource> thin;
        const Segment& seg = d.file().model.segments[i];
        thin->SetRadius(std::max(kGhostRadiusFactor * seg.shape.radius, 0.015));
        thin->SetCylinderLength(std::abs(seg.shape.length));
        thin->SetThetaResolution(8);
        thin->SetPhiResolution(6);
        vtkNew<vtkTransformPolyDataFilter> placed;
        placed->SetTransform(transform);
        placed->SetInputConnection(thin->GetOutputPort());
        all->AddInputConnection(placed->GetOutputPort());
      }
    }
    all->Update();
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(all->GetOutput());
    ghosts = vtkSmartPointer<vtkActor>::New();
    ghosts->SetMapper(mapper);
    // Flat, unlit silhouettes rather than translucent bodies: VTK's order-independent
    // transparency would cost more than the rest of the frame in software OpenGL (measured: 16
    // against 40 frames per second). Without shading they read as shadows of the lit,
    // coloured body instead of as more bodies.
    set_colour(ghosts, colour);
    ghosts->GetProperty()->SetLighting(false);
    ghosts->PickableOff();
    renderer->AddActor(ghosts);
  }

  void update_legend_actors() {
    force_bar->SetLookupTable(magnitude_table(force_scale.full_scale()));
    force_bar->SetTitle("residual force (N)");
    moment_bar->SetLookupTable(magnitude_table(moment_scale.full_scale()));
    moment_bar->SetTitle("residual moment (N·m)");
    std::string text =
        "Arrows at the CoM (yellow ball), green = small, red = large\n"
        "  single head: residual force, " +
        force_scale.legend("N") + "\n  double head: residual moment, " + moment_scale.legend("N·m");
    if (options.joint_arrows) text += "\n  at the joints: joint forces, " + joint_scale.legend("N");
    text += "\nLines: white = ballistic CoM parabola, orange = this motion's CoM";
    if (options.ghosts) text += "\nThin pale figures: the keyframe poses";
    legend->SetInput(text.c_str());
  }

  void apply_visibility() {
    for (auto& a : trampoline)
      a->SetVisibility(options.trampoline);
    grid->SetVisibility(options.floor_grid);
    if (parabola) parabola->SetVisibility(options.parabola);
    if (trace) trace->SetVisibility(options.com_trace);
    if (ghosts) ghosts->SetVisibility(options.ghosts);
    const bool has_doc = document != nullptr;
    force_bar->SetVisibility(has_doc && options.residual_arrows);
    moment_bar->SetVisibility(has_doc && options.residual_arrows);
    legend->SetVisibility(has_doc && (options.residual_arrows || options.joint_arrows));
    physics->SetVisibility(has_doc && options.physics_text);
    com_marker->SetVisibility(has_doc);
    if (!has_doc) {
      force_arrow->SetVisibility(false);
      moment_arrow->SetVisibility(false);
    }
  }

  void place_arrow(vtkActor* actor, const Eigen::Vector3d& origin, const Eigen::Vector3d& vector,
                   const GlyphScale& scale, double thickness, bool shown) {
    const double magnitude = vector.norm();
    const double length = scale.length(magnitude);
    if (!shown || length < 1e-4) {
      actor->SetVisibility(false);
      return;
    }
    actor->SetVisibility(true);
    set_matrix(actor, arrow_transform(origin, vector, length, thickness));
    set_colour(actor, scale.colour(magnitude));
  }

  void update_time(bool playing = false) {
    if (!document) return;
    const SampleRecord s = document->sample_at(stage, time);
    const RotationSample r = document->rotation_at(stage, time);
    current_com = s.com;
    pose(s);
    {
      Eigen::Affine3d t = Eigen::Affine3d::Identity();
      t.translate(s.segment_position[face_segment]);
      t.rotate(s.segment_rotation[face_segment]);
      t.translate(face_offset);
      set_matrix(face, t);
    }
    Eigen::Affine3d at_com = Eigen::Affine3d::Identity();
    at_com.translate(s.com);
    set_matrix(com_marker, at_com);

    const Eigen::Vector3d force = s.residual.head<3>();
    const Eigen::Vector3d moment = s.residual.tail<3>();
    place_arrow(force_arrow, s.com, force, force_scale, 0.9, options.residual_arrows);
    place_arrow(moment_arrow, s.com, moment, moment_scale, 0.6, options.residual_arrows);
    for (std::size_t i = 0; i < joint_arrows.size(); ++i) {
      const int seg = static_cast<int>(i) + 1;
      // joint_wrench is the parent's push on the child, child frame: rotate into the world.
      const Eigen::Vector3d f = s.segment_rotation[seg] * s.joint_wrench[seg].head<3>();
      place_arrow(joint_arrows[i], s.segment_position[seg], f, joint_scale, 0.45,
                  options.joint_arrows);
    }

    if (preset == CameraPreset::kFollow) apply_camera();
    const auto now = std::chrono::steady_clock::now();
    if (playing && now - last_text < std::chrono::duration<double>(1.0 / kTextRefreshPerSecond))
      return;
    last_text = now;
    const MotionFile& file = document->file();
    title->SetInput((file.motion.name + "\n" +
                     (stage == Stage::kAfter ? "optimised motion (after)"
                                             : "interpolated keyframes (before optimisation)") +
                     printf_string("\nt = %.3f s of %.3f s", time, document->duration()))
                        .c_str());
    const Eigen::Vector3d& l = r.angular_momentum;
    physics->SetInput(
        (printf_string("Rotation about the centre of mass\n"
                       "angular momentum L = (%.1f, %.1f, %.1f) kg·m²/s\n"
                       "moment of inertia about x  I_xx = %.2f kg·m²\n"
                       "somersault rate ω_x = %.2f rad/s   twist rate %.2f rad/s\n"
                       "somersaults so far %.2f   twists %.2f\n",
                       tidy(l.x(), 1), tidy(l.y(), 1), tidy(l.z(), 1), r.somersault_inertia,
                       tidy(r.somersault_rate, 2), tidy(r.twist_rate, 2), tidy(r.somersaults, 2),
                       tidy(r.twists, 2)) +
         printf_string("Residual (zero in a valid flight)\n|F| = %.1f N   |M| = %.1f N·m",
                       force.norm(), moment.norm()))
            .c_str());
  }

  void apply_camera() {
    vtkCamera* camera = renderer->GetActiveCamera();
    // Side (and follow) by default: from the athlete's right (−x), so they face screen-right
    // and somersault in the screen plane.
    Eigen::Vector3d towards_camera(-1, 0, 0);
    Eigen::Vector3d up = Eigen::Vector3d::UnitY();
    switch (preset) {
      case CameraPreset::kSide:
        break;
      case CameraPreset::kFollow:
        // Three-quarter view from the right, in front and a little above: both sides of the
        // body and its depth show while it stays large in the frame.
        towards_camera = Eigen::Vector3d(-1.0, 0.35, 0.8).normalized();
        break;
      case CameraPreset::kFront:
        towards_camera = Eigen::Vector3d(0, 0, 1);
        up = Eigen::Vector3d::UnitY();
        break;
      case CameraPreset::kTop:
        towards_camera = Eigen::Vector3d(0, 1, 0);
        up = Eigen::Vector3d::UnitZ();
        break;
    }
    camera->SetViewAngle(30.0);
    if (preset == CameraPreset::kFollow) {
      const Eigen::Vector3d position =
          current_com + kFollowDistance * towards_camera + Eigen::Vector3d(0, 0.8, 0);
      camera->SetFocalPoint(current_com.x(), current_com.y(), current_com.z());
      camera->SetPosition(position.x(), position.y(), position.z());
      camera->SetViewUp(up.x(), up.y(), up.z());
    } else {
      const Eigen::Vector3d centre(0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
                                   0.5 * (bounds[4] + bounds[5]));
      const Eigen::Vector3d position = centre + 20.0 * towards_camera;
      camera->SetFocalPoint(centre.x(), centre.y(), centre.z());
      camera->SetPosition(position.x(), position.y(), position.z());
      camera->SetViewUp(up.x(), up.y(), up.z());
      renderer->ResetCamera(bounds);
      // ResetCamera fits a bounding sphere; the flight is tall and narrow, so come closer.
      camera->Dolly(1.35);
    }
    // The overlay shares this camera and so its clipping range, which covers its props too.
    renderer->ResetCameraClippingRange();
  }
};

BodyScene::BodyScene() : impl_(std::make_unique<Impl>()) {
  impl_->apply_visibility();
  impl_->apply_camera();
}

BodyScene::~BodyScene() = default;

void BodyScene::attach(vtkRenderWindow* window) {
  window->SetNumberOfLayers(2);
  window->AddRenderer(impl_->renderer);
  window->AddRenderer(impl_->overlay);
}

void BodyScene::set_document(const Document* document, Stage stage) {
  Impl& d = *impl_;
  d.clear_body();
  d.document = document && document->loaded() ? document : nullptr;
  if (!d.document) {
    d.title->SetInput("Open a motion file (File > Open, or drop a *.motion.json here)");
    d.apply_visibility();
    return;
  }
  d.stage = document->available(stage);
  d.build_body(document->file().model);
  d.apply_highlight();
  d.build_paths(*document);
  d.build_ghosts(*document);
  d.force_scale = document->residual_force_scale(kArrowMaxLength);
  d.moment_scale = document->residual_moment_scale(kArrowMaxLength);
  d.joint_scale = document->joint_force_scale(kJointArrowMaxLength);
  d.update_legend_actors();
  d.time = std::clamp(d.time, 0.0, document->duration());
  d.apply_visibility();
  d.update_time();
}

void BodyScene::set_options(const SceneOptions& options) {
  impl_->options = options;
  impl_->update_legend_actors();
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
  impl_->preset = preset;
  impl_->apply_camera();
}

CameraPreset BodyScene::camera() const {
  return impl_->preset;
}

void BodyScene::reset_camera() {
  impl_->apply_camera();
}

int BodyScene::segment_at(int x, int y) const {
  Impl& d = *impl_;
  if (!d.document || d.segments.empty()) return -1;
  if (!d.picker->Pick(x, y, 0.0, d.renderer)) return -1;
  const vtkActor* actor = d.picker->GetActor();
  for (std::size_t i = 0; i < d.segments.size(); ++i)
    if (d.segments[i] == actor) return static_cast<int>(i);
  if (actor && actor == d.face) return d.face_segment;
  return -1;
}

void BodyScene::set_highlight(int segment) {
  Impl& d = *impl_;
  d.highlight = segment < 0 ? -1 : segment;
  d.apply_highlight();
  d.update_time();
}

int BodyScene::highlight() const {
  return impl_->highlight;
}

}  // namespace saltus::gui
