#pragma once
/// @file
/// The words in the 3D view (a layer of BodyScene; private to gui/scene): what is shown and when
/// (top left), the residual and the spin now (top right), what the arrows and lines mean (bottom
/// left), the caption of the whole-flight inset, and for videos a line with the time and the
/// residual. Text sizes follow the view's height, so that a small window does not crowd them.

#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTextActor.h>

#include <array>
#include <string>
#include <vector>

namespace saltus::gui::scene {

class TextLayer {
 public:
  TextLayer(vtkRenderer* renderer, vtkRenderer* inset);

  void set_title(const std::string& text);
  std::string title() const;
  void set_numbers(const std::string& text);
  void set_legend(const std::string& text);
  void set_banner(const std::string& text);
  void set_visible(bool title, bool numbers, bool legend, bool banner, bool inset_caption);
  /// Text sizes for a view `height` pixels tall.
  void fit(int height);
  /// The boxes of the words drawn in `renderer`'s corners (title, numbers, legend; the hidden
  /// ones left out), display pixels {x0, x1, y0, y1}: where no label in the scene may go.
  std::vector<std::array<double, 4>> boxes(vtkRenderer* renderer) const;

 private:
  vtkSmartPointer<vtkTextActor> title_, numbers_, legend_, banner_, inset_caption_;
  int height_ = 0;
};

/// `text` broken into lines of at most `width` characters at spaces (long words stay whole).
std::string wrapped(const std::string& text, std::size_t width);

}  // namespace saltus::gui::scene
