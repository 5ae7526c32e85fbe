#pragma once
/// @file
/// The 3D scene of one motion, in layers (each its own class in gui/scene): the athlete drawn
/// from the model's shapes (body_layer), the apparatus the motion implies and a floor grid
/// (environment_layer), the CoM parabola, the motion's CoM path and the CoM now (path_layer),
/// the residual force and moment arrows and optional joint-force arrows (glyph_layer), and the
/// words (text_layer). The cameras frame the athlete and follow it (scene_camera); a small
/// inset shows the whole flight meanwhile. A segment can be picked at a pixel and highlighted.

#include <memory>
#include <optional>
#include <string>
#include <vector>

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

  /// Adds the scene's renderers to a window: the scene, the whole-flight inset in a corner of
  /// it, and on a layer above both the CoM ball and the residual arrows, which start inside the
  /// trunk and must not be hidden by it.
  void attach(vtkRenderWindow* window);

  /// Shows a stage of the document (which must stay alive and unchanged until the next call);
  /// null clears the scene. Keeps the camera (call reset_camera() to frame a new motion).
  void set_document(const Document* document, Stage stage);
  void set_options(const SceneOptions& options);
  const SceneOptions& options() const;

  /// Poses the body and updates the arrows, CoM marker and texts at time t (s). With
  /// `playing` the texts refresh at most kTextRefreshPerSecond times a second: numbers changing
  /// every frame cannot be read, and re-rasterising them costs a sixth of a software-GL frame.
  void set_time(double t, bool playing = false);
  static constexpr double kTextRefreshPerSecond = 8.0;
  double time() const;

  /// Frames the athlete as if it stood `height` m tall (nullopt: its own standing height), so
  /// that views side by side share one scale and a shorter athlete looks shorter. Takes effect
  /// with the next set_document.
  void set_framing_height(std::optional<double> height);

  /// Points the camera (SceneCamera): every preset frames the athlete and follows it.
  void set_camera(CameraPreset preset);
  CameraPreset camera() const;
  /// The current preset again, at the current time.
  void reset_camera();

  /// Arrow scales from these typical sizes (compare: both views share the larger run's), or,
  /// with nullopt, the document's one scale for both stages of its run (the default,
  /// Document::arrow_typicals).
  void set_glyph_typicals(std::optional<GlyphTypicals> typicals);
  /// The residual force arrow as drawn now: its length in metres (0 when not drawn), and the
  /// force its scale draws at full length (the legend's "0.6 m = 500 N").
  double residual_force_arrow_length() const;
  double residual_force_full_scale() const;
  /// The legend's text (arrow scales, lines, figures) as the view shows it.
  std::string legend() const;
  /// The title's text (the motion, what is shown of it, the time) as the view shows it.
  std::string title() const;
  /// Anti-aliased edges (FXAA, a post-processing pass). Off by default: in software OpenGL the
  /// pass costs several frames' worth of time, so the app draws moving pictures without it and
  /// a still picture, an export or a video frame with it.
  void set_antialiasing(bool on);
  bool antialiasing() const;
  /// For videos: the time and the residual in a line at the top right instead of the numbers
  /// and the legend.
  void set_video_overlay(bool on);

  /// The body segment drawn at a pixel of the render window (x from the left, y from the
  /// bottom, device pixels): its index in the model, the nearest along the line of sight; -1
  /// where no segment is (background, apparatus, arrows, or no document).
  int segment_at(int x, int y) const;
  /// A second figure beside the athlete flying `samples` (a what-if flight of the same take-off,
  /// its samples in time order, one rotation per segment of the document's model), labelled
  /// `label`; an empty vector removes it. It stays across set_document (the What if panel says
  /// when it goes) but is drawn only while its samples fit the document's model. Posed at the
  /// time shown, between its samples.
  /// `legend`: the legend's line for it.
  void set_what_if(
      std::vector<SampleRecord> samples, const std::string& label,
      const std::string& legend = "the What if panel's free flight from the same take-off");
  bool what_if_shown() const;
  /// Where the what-if figure is drawn now, its offset from the flight it flies included (world,
  /// m), and the sample it is posed at; nullopt when it is not drawn.
  std::optional<SampleRecord> what_if_pose() const;

  /// Draws a segment brighter and outlined (-1: none). Stays across set_document while the
  /// index exists in the new model.
  void set_highlight(int segment);
  int highlight() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace saltus::gui
