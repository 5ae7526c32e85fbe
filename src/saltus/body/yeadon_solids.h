#pragma once
/// @file
/// The solids of Yeadon's geometric inertia model (M. R. Yeadon, "The simulation of aerial
/// movement II: a mathematical inertia model of the human body", J. Biomech. 23(1):67-74,
/// 1990): the stadium (a rectangle with a half-disc on each short side), the stadium solid (the
/// solid between two parallel stadia joined by linear interpolation) and the semi-ellipsoid.
/// Mass, CoM and inertia are the exact integrals (polynomials in the height, integrated by a
/// Gauss–Legendre rule that is exact for their degree). docs/method.md, "Yeadon's model".

#include <string>

#include "saltus/body/mass_properties.h"

namespace saltus {

/// A stadium: half-length `t` of its straight sides (>= 0) and radius `r` of its ends (> 0), m.
/// Its width is 2t + 2r, its depth 2r, its perimeter 4t + 2πr. `anterior_posterior` turns its
/// long direction from medio-lateral (x) to antero-posterior (z), as at the heel.
struct Stadium {
  double t = 0.0;
  double r = 0.0;
  bool anterior_posterior = false;
  double width() const { return 2.0 * t + 2.0 * r; }
  double perimeter() const;
  double area() const;
};

/// From a perimeter and a width: t = (πw − p)/(2π − 4), r = (p − 2w)/(2π − 4). Only
/// 2w < p <= πw is a stadium; `status` says which side of that range p is on (-1 too small for
/// the width, +1 too large for it: rounder than a circle, 0 a stadium). The caller decides; the
/// returned stadium is meaningful only for status 0.
Stadium stadium_from_perimeter_width(double perimeter, double width, int* status);
/// A circle: t = 0.
Stadium circle_from_perimeter(double perimeter);

/// Solid between stadium `bottom` at height 0 and `top` at height h > 0 along the solid's axis,
/// with density ρ (kg/m³). Frame: origin at the bottom stadium's centre, y along the axis
/// (towards `top`), x medio-lateral, z antero-posterior. Either stadium being
/// antero-posterior makes the whole solid so (its other end must then be a circle).
RigidMass stadium_solid(double density, const Stadium& bottom, const Stadium& top, double h);

/// Volume of that solid, m³.
double stadium_solid_volume(const Stadium& bottom, const Stadium& top, double h);

/// Half an ellipsoid: a circular base of radius r at height 0, the pole at height h on +y.
/// Mass ρ·(2/3)πr²h, CoM at 3h/8, inertia about the CoM: m·r²·2/5 about y, m(r² + h²)/5 −
/// m(3h/8)² about x and z.
RigidMass semi_ellipsoid(double density, double r, double h);

}  // namespace saltus
