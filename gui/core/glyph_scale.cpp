#include "core/glyph_scale.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "saltus/base/text_format.h"

namespace saltus::gui {

double nice_ceiling(double x) {
  if (!(x > 0) || !std::isfinite(x)) return 1.0;
  const double decade = std::pow(10.0, std::floor(std::log10(x)));
  for (double m : {1.0, 2.0, 5.0, 10.0}) {
    // A relative slack so that exact round numbers (50 → 50) are not pushed to the next step.
    if (m * decade >= x * (1 - 1e-12)) return m * decade;
  }
  return 10.0 * decade;
}

Rgb magnitude_colour(double fraction) {
  const double f = std::isfinite(fraction) ? std::clamp(fraction, 0.0, 1.0) : 1.0;
  const Rgb green{0.20, 0.72, 0.30}, yellow{0.98, 0.80, 0.10}, red{0.86, 0.10, 0.10};
  const Rgb& a = f < 0.5 ? green : yellow;
  const Rgb& b = f < 0.5 ? yellow : red;
  const double u = f < 0.5 ? f / 0.5 : (f - 0.5) / 0.5;
  return {a.r + u * (b.r - a.r), a.g + u * (b.g - a.g), a.b + u * (b.b - a.b)};
}

GlyphScale::GlyphScale(double typical, double max_length_m) {
  if (!(max_length_m > 0)) throw std::invalid_argument("glyph length must be positive");
  full_scale_ = nice_ceiling(typical);
  max_length_m_ = max_length_m;
}

double GlyphScale::length(double magnitude) const {
  return std::min(max_length_m_ * std::max(0.0, magnitude) / full_scale_,
                  kLengthCap * max_length_m_);
}

double GlyphScale::fraction(double magnitude) const {
  return std::clamp(magnitude / full_scale_, 0.0, 1.0);
}

std::string GlyphScale::legend(const std::string& unit) const {
  return legend_number(max_length_m_) + " m = " + legend_number(full_scale_) + " " + unit;
}

std::string legend_number(double value) {
  char buffer[32];
  const double rounded = std::round(value);
  if (std::abs(value) >= 1.0 && std::abs(value) < 1e6 && std::abs(value - rounded) < 1e-9)
    std::snprintf(buffer, sizeof buffer, "%.0f", rounded);
  else
    std::snprintf(buffer, sizeof buffer, "%.3g", value);
  return buffer;
}

}  // namespace saltus::gui
