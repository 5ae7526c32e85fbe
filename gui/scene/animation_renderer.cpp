#include "scene/animation_renderer.h"

#include <vtkNew.h>
#include <vtkRenderWindow.h>
#include <vtkUnsignedCharArray.h>

#include <cstring>
#include <stdexcept>

#include "scene/body_scene.h"

namespace saltus::gui {

struct AnimationRenderer::Impl {
  vtkNew<vtkRenderWindow> window;
  vtkNew<vtkUnsignedCharArray> pixels;
  BodyScene scene;
  std::vector<unsigned char> frame;
};

AnimationRenderer::AnimationRenderer(int width, int height)
    : impl_(std::make_unique<Impl>()), width_(width), height_(height) {
  if (width < 16 || height < 16) throw std::invalid_argument("frame size too small");
  impl_->window->SetOffScreenRendering(1);
  impl_->window->SetSize(width, height);
  impl_->window->SetMultiSamples(0);
  impl_->scene.attach(impl_->window);
  impl_->scene.set_video_overlay(true);
  impl_->scene.set_antialiasing(true);  // a video frame is a still picture: worth the pass
  impl_->frame.resize(static_cast<std::size_t>(width) * height * 3);
}

AnimationRenderer::~AnimationRenderer() {
  impl_->scene.set_document(nullptr, Stage::kBefore);
}

void AnimationRenderer::set_document(const Document* document, Stage stage,
                                     const SceneOptions& options, CameraPreset camera) {
  impl_->scene.set_options(options);
  impl_->scene.set_document(document, stage);
  impl_->scene.set_camera(camera);
  impl_->scene.set_time(0.0);
  impl_->scene.reset_camera();
}

const std::vector<unsigned char>& AnimationRenderer::render(double t) {
  impl_->scene.set_time(t);
  impl_->window->Render();
  impl_->window->GetPixelData(0, 0, width_ - 1, height_ - 1, 0, impl_->pixels);
  const unsigned char* rows = impl_->pixels->GetPointer(0);
  const std::size_t row_bytes = static_cast<std::size_t>(width_) * 3;
  // OpenGL's rows go up from the bottom, video frames down from the top.
  for (int y = 0; y < height_; ++y)
    std::memcpy(impl_->frame.data() + static_cast<std::size_t>(y) * row_bytes,
                rows + static_cast<std::size_t>(height_ - 1 - y) * row_bytes, row_bytes);
  return impl_->frame;
}

}  // namespace saltus::gui
