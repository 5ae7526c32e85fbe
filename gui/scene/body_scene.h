#pragma once
/// @file
/// The 3D scene of one motion: the body's segments as capsules (left blue, right orange), the
/// trampoline bed and a floor grid, the ballistic CoM parabola, the motion's own CoM trace and the
/// current CoM, the residual force and moment about the CoM as arrows scaled and coloured by
/// magnitude (with legends), optional joint-force arrows, translucent keyframe poses and a text
/// panel of the rotation quantities. Camera presets: side, front, top, follow. A segment can be
/// picked at a pixel and highlighted.

#include <memory>

#include "core/document.h"
#include "core/scene_options.h"

class vtkRenderWindow;

namespace saltus::gui {

class BodyScene {
 public:
  BodyScene();
  ~BodyScene();
  BodyScene(const BodyScene&) = delete;
  BodyScene& operator=(const BodyScene&) = delete;

  /// Adds the scene's renderers to a window: the scene itself, and on a layer above it the CoM
  /// marker and the residual arrows, which start inside the trunk and must not be hidden by it.
  void attach(vtkRenderWindow* window);

  /// Shows a stage of the document (which must stay alive and unchanged until the next call);
  /// null clears the scene. Keeps the camera (call reset_camera() to fit a new flight).
  void set_document(const Document* document, Stage stage);
  void set_options(const SceneOptions& options);
  const SceneOptions& options() const;

  /// Poses the body and updates the arrows, CoM marker and texts at time t (s). With
  /// `playing` the texts refresh at most kTextRefreshPerSecond times a second: numbers changing
  /// every frame cannot be read, and re-rasterising them costs a sixth of a software-GL frame.
  void set_time(double t, bool playing = false);
  static constexpr double kTextRefreshPerSecond = 8.0;
  double time() const;

  /// Points the camera; kFollow keeps following the CoM as time changes.
  void set_camera(CameraPreset preset);
  CameraPreset camera() const;
  /// The current preset again, fitted to the whole flight.
  void reset_camera();

  /// The body segment drawn at a pixel of the render window (x from the left, y from the
  /// bottom, device pixels): its index in the model, the nearest along the line of sight; -1
  /// where no segment is (background, trampoline, arrows, or no document). The red face marker
  /// counts as the segment it sits on.
  int segment_at(int x, int y) const;
  /// Draws a segment brighter and outlined (-1: none). Stays across set_document while the
  /// index exists in the new model.
  void set_highlight(int segment);
  int highlight() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace saltus::gui
