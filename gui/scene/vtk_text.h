#pragma once
/// @file
/// One font for every VTK text (3D overlays and charts). VTK's embedded fonts lack Greek letters
/// and symbols the labels use (ω, ², ·, √), so DejaVu Sans is used when installed (Debian's
/// fontconfig depends on it); otherwise VTK's Arial stands in.

class vtkTextProperty;

namespace saltus::gui {

/// Font file, size (points) and colour (each in [0, 1]) for a text property.
void apply_font(vtkTextProperty* property, int size, double r = 0.1, double g = 0.1, double b = 0.1,
                bool bold = false);

}  // namespace saltus::gui
