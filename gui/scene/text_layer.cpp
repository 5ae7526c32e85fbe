#include "scene/text_layer.h"

#include <vtkCoordinate.h>
#include <vtkTextProperty.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "scene/vtk_text.h"

namespace saltus::gui::scene {

namespace {

vtkSmartPointer<vtkTextActor> text_actor(double x, double y, int horizontal, int vertical) {
  auto actor = vtkSmartPointer<vtkTextActor>::New();
  actor->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  actor->GetPositionCoordinate()->SetValue(x, y);
  vtkTextProperty* p = actor->GetTextProperty();
  apply_font(p, 14, 0.95, 0.95, 0.97);
  p->SetJustification(horizontal);
  p->SetVerticalJustification(vertical);
  p->SetLineSpacing(1.15);
  return actor;
}

}  // namespace

std::string wrapped(const std::string& text, std::size_t width) {
  std::istringstream words(text);
  std::string word, line, out;
  while (words >> word) {
    if (!line.empty() && line.size() + 1 + word.size() > width) {
      out += (out.empty() ? "" : "\n") + line;
      line.clear();
    }
    line += (line.empty() ? "" : " ") + word;
  }
  if (!line.empty()) out += (out.empty() ? "" : "\n") + line;
  return out;
}

TextLayer::TextLayer(vtkRenderer* renderer, vtkRenderer* inset) {
  title_ = text_actor(0.012, 0.985, VTK_TEXT_LEFT, VTK_TEXT_TOP);
  numbers_ = text_actor(0.988, 0.985, VTK_TEXT_RIGHT, VTK_TEXT_TOP);
  legend_ = text_actor(0.012, 0.015, VTK_TEXT_LEFT, VTK_TEXT_BOTTOM);
  banner_ = text_actor(0.988, 0.985, VTK_TEXT_RIGHT, VTK_TEXT_TOP);
  inset_caption_ = text_actor(0.04, 0.96, VTK_TEXT_LEFT, VTK_TEXT_TOP);
  inset_caption_->SetInput("whole flight");
  for (vtkTextActor* t : {title_.Get(), numbers_.Get(), legend_.Get(), banner_.Get()})
    renderer->AddActor2D(t);
  inset->AddActor2D(inset_caption_);
  fit(600);
}

void TextLayer::set_title(const std::string& text) {
  title_->SetInput(text.c_str());
}
std::string TextLayer::title() const {
  const char* text = title_->GetInput();
  return text ? text : "";
}

void TextLayer::set_numbers(const std::string& text) {
  numbers_->SetInput(text.c_str());
}
void TextLayer::set_legend(const std::string& text) {
  legend_->SetInput(text.c_str());
}
void TextLayer::set_banner(const std::string& text) {
  banner_->SetInput(text.c_str());
}

void TextLayer::set_visible(bool title, bool numbers, bool legend, bool banner,
                            bool inset_caption) {
  title_->SetVisibility(title);
  numbers_->SetVisibility(numbers);
  legend_->SetVisibility(legend);
  banner_->SetVisibility(banner);
  inset_caption_->SetVisibility(inset_caption);
}

void TextLayer::fit(int height) {
  if (height == height_ || height <= 0) return;
  height_ = height;
  // About 45 lines of title text per view height, within what stays readable and small.
  const int base = std::clamp(static_cast<int>(std::lround(height / 45.0)), 11, 19);
  apply_font(title_->GetTextProperty(), base + 1, 1.0, 1.0, 1.0, true);
  apply_font(numbers_->GetTextProperty(), base, 0.95, 0.95, 0.97);
  apply_font(legend_->GetTextProperty(), std::max(10, base - 2), 0.92, 0.92, 0.95);
  apply_font(banner_->GetTextProperty(), base + 1, 1.0, 1.0, 1.0, true);
  apply_font(inset_caption_->GetTextProperty(), std::max(10, base - 3), 0.85, 0.88, 0.92);
  // A shadow keeps light text readable over the light sky and the white parabola.
  for (vtkTextActor* t : {title_.Get(), numbers_.Get(), legend_.Get(), banner_.Get()}) {
    t->GetTextProperty()->ShadowOn();
    t->GetTextProperty()->SetShadowOffset(1, -1);
  }
}

std::vector<std::array<double, 4>> TextLayer::boxes(vtkRenderer* renderer) const {
  std::vector<std::array<double, 4>> out;
  for (vtkTextActor* t : {title_.Get(), numbers_.Get(), legend_.Get()}) {
    if (!t->GetVisibility() || !t->GetInput() || !*t->GetInput()) continue;
    // The box is about the text's anchor (its position, justified): moved to where it is.
    std::array<double, 4> box{};
    t->GetBoundingBox(renderer, box.data());
    const int* at = t->GetPositionCoordinate()->GetComputedDisplayValue(renderer);
    out.push_back({box[0] + at[0], box[1] + at[0], box[2] + at[1], box[3] + at[1]});
  }
  return out;
}

}  // namespace saltus::gui::scene
