#include "scene/vtk_text.h"

#include <vtkTextProperty.h>

#include <filesystem>
#include <string>

namespace saltus::gui {

namespace {
std::string find_font(const char* name) {
  for (const char* folder : {"/usr/share/fonts/truetype/dejavu/", "/usr/share/fonts/dejavu/"}) {
    const std::string candidate = std::string(folder) + name;
    if (std::filesystem::exists(candidate)) return candidate;
  }
  return {};
}

const std::string& font_file(bool bold) {
  static const std::string regular = find_font("DejaVuSans.ttf");
  static const std::string heavy = find_font("DejaVuSans-Bold.ttf");
  return bold && !heavy.empty() ? heavy : regular;
}
}  // namespace

void apply_font(vtkTextProperty* property, int size, double r, double g, double b, bool bold) {
  const std::string& file = font_file(bold);
  if (!file.empty()) {
    property->SetFontFamily(VTK_FONT_FILE);
    property->SetFontFile(file.c_str());
  } else {
    property->SetFontFamilyToArial();
  }
  property->SetFontSize(size);
  property->SetColor(r, g, b);
  property->SetBold(bold);
  property->SetItalic(false);
  property->SetShadow(false);
}

}  // namespace saltus::gui
