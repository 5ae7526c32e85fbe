#pragma once
/// @file
/// How force and moment arrows are sized and coloured: one fixed scale per quantity for the whole
/// motion (before and after alike), so an arrow's length can be read against the legend and
/// arrows of different frames and stages compare directly.

#include <string>

#include "core/chart_spec.h"

#include "saltus/base/text_format.h"

namespace saltus::gui {

/// Smallest 1, 2 or 5 × 10^k that is >= x (x > 0); 1 for x <= 0 or not finite.
double nice_ceiling(double x);

/// Colour for a magnitude as a fraction of full scale (clamped to [0, 1]): green (small: close
/// to physically valid) through yellow to red (large).
Rgb magnitude_colour(double fraction);

class GlyphScale {
 public:
  GlyphScale() = default;
  /// @param typical       a large but typical magnitude (N or N·m), >= 0: the scale's full
  ///                      value is nice_ceiling(typical), a round number for the legend
  /// @param max_length_m  arrow length at full scale, m (> 0)
  GlyphScale(double typical, double max_length_m);

  /// Arrows never grow beyond this many times max_length (a rare spike stays on screen).
  static constexpr double kLengthCap = 2.0;

  /// Round magnitude drawn max_length_m long.
  double full_scale() const { return full_scale_; }
  double max_length() const { return max_length_m_; }
  /// Arrow length in metres for a magnitude: proportional, capped at kLengthCap × max_length.
  double length(double magnitude) const;
  /// magnitude / full scale, clamped to [0, 1].
  double fraction(double magnitude) const;
  Rgb colour(double magnitude) const { return magnitude_colour(fraction(magnitude)); }
  /// Legend text, e.g. "1 m = 50 N", "1 m = 1000 N".
  std::string legend(const std::string& unit) const;

 private:
  double full_scale_ = 1.0;
  double max_length_m_ = 1.0;
};

/// A legend's number: up to 3 significant digits without trailing zeros, and whole numbers up to
/// a million written out ("0.25", "50", "1000", "20000"; never "1e+03").
std::string legend_number(double value);

}  // namespace saltus::gui
