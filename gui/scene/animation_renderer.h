#pragma once
/// @file
/// Renders a motion frame by frame offscreen, for video export: its own BodyScene in its own
/// render window of a fixed size, showing a stage of a document with the given display options
/// and camera, the time and the residual written in the picture. No Qt.

#include <memory>
#include <vector>

#include "core/document.h"
#include "core/scene_options.h"

namespace saltus::gui {

class AnimationRenderer {
 public:
  /// @param width, height  frame size in pixels (even numbers suit video encoders)
  AnimationRenderer(int width, int height);
  ~AnimationRenderer();
  AnimationRenderer(const AnimationRenderer&) = delete;
  AnimationRenderer& operator=(const AnimationRenderer&) = delete;

  /// What to show (the document must outlive the renderer), as the 3D view shows it.
  void set_document(const Document* document, Stage stage, const SceneOptions& options,
                    CameraPreset camera);
  /// The frame at time t (s): width × height × 3 bytes, RGB, rows from the top.
  const std::vector<unsigned char>& render(double t);
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  int width_, height_;
};

}  // namespace saltus::gui
