#include "saltus/body/yeadon_solids.h"

#include <cmath>
#include <stdexcept>

#include "saltus/math/gauss_legendre.h"

namespace saltus {

double Stadium::perimeter() const {
  return 4.0 * t + 2.0 * M_PI * r;
}

double Stadium::area() const {
  return 4.0 * r * t + M_PI * r * r;
}

Stadium stadium_from_perimeter_width(double perimeter, double width, int* status) {
  Stadium s;
  s.t = (M_PI * width - perimeter) / (2.0 * M_PI - 4.0);
  s.r = (perimeter - 2.0 * width) / (2.0 * M_PI - 4.0);
  if (status) *status = !(s.r > 0.0) ? -1 : (s.t < 0.0 ? 1 : 0);
  return s;
}

Stadium circle_from_perimeter(double perimeter) {
  Stadium s;
  s.r = perimeter / (2.0 * M_PI);
  return s;
}

namespace {

/// The cross-section at fraction u of the height: t and r interpolated linearly.
struct Section {
  double t, r;
};

Section section_at(const Stadium& a, const Stadium& b, double u) {
  return {a.t + (b.t - a.t) * u, a.r + (b.r - a.r) * u};
}

/// ∫ x² dA over a stadium whose straight sides run along x (the long direction): the rectangle
/// 2t × 2r plus two half-discs centred at x = ±t.
double second_moment_long(const Section& s) {
  return 4.0 * s.r * s.t * s.t * s.t / 3.0 + M_PI * s.r * s.r * s.t * s.t +
         8.0 * s.r * s.r * s.r * s.t / 3.0 + M_PI * std::pow(s.r, 4) / 4.0;
}

/// ∫ y² dA across the long direction.
double second_moment_short(const Section& s) {
  return 4.0 * s.t * s.r * s.r * s.r / 3.0 + M_PI * std::pow(s.r, 4) / 4.0;
}

/// Every integrand is a polynomial of degree at most 4 in u: 4 nodes are exact to degree 7.
const QuadratureRule& rule() {
  static const QuadratureRule r = gauss_legendre(4);
  return r;
}

}  // namespace

double stadium_solid_volume(const Stadium& bottom, const Stadium& top, double h) {
  double v = 0.0;
  const QuadratureRule& q = rule();
  for (std::size_t i = 0; i < q.nodes.size(); ++i) {
    const Section s = section_at(bottom, top, q.nodes[i]);
    v += q.weights[i] * (4.0 * s.r * s.t + M_PI * s.r * s.r);
  }
  return v * h;
}

RigidMass stadium_solid(double density, const Stadium& bottom, const Stadium& top, double h) {
  if (!(h > 0.0) || !(density > 0.0))
    throw std::invalid_argument("stadium_solid: height and density must be positive");
  double area = 0.0, first = 0.0, second = 0.0, long_moment = 0.0, short_moment = 0.0;
  const QuadratureRule& q = rule();
  for (std::size_t i = 0; i < q.nodes.size(); ++i) {
    const double u = q.nodes[i];
    const double w = q.weights[i];
    const Section s = section_at(bottom, top, u);
    const double a = 4.0 * s.r * s.t + M_PI * s.r * s.r;
    const double y = u * h;
    area += w * a;
    first += w * a * y;
    second += w * a * y * y;
    long_moment += w * second_moment_long(s);
    short_moment += w * second_moment_short(s);
  }
  RigidMass out;
  out.mass = density * h * area;
  const double y_com = density * h * first / out.mass;
  out.com = Eigen::Vector3d(0.0, y_com, 0.0);
  // About the base, then moved to the CoM along y.
  const double axial_spread = density * h * second - out.mass * y_com * y_com;
  double along_long = density * h * long_moment;    // ∫ (long direction)² dm
  double along_short = density * h * short_moment;  // ∫ (short direction)² dm
  if (bottom.anterior_posterior || top.anterior_posterior) std::swap(along_long, along_short);
  // x medio-lateral, z antero-posterior: I_xx = ∫ y² + z², I_zz = ∫ x² + y², I_yy = ∫ x² + z².
  out.inertia = Eigen::Vector3d(axial_spread + along_short, along_long + along_short,
                                axial_spread + along_long)
                    .asDiagonal();
  return out;
}

RigidMass semi_ellipsoid(double density, double r, double h) {
  if (!(h > 0.0) || !(r > 0.0) || !(density > 0.0))
    throw std::invalid_argument("semi_ellipsoid: sizes and density must be positive");
  RigidMass out;
  out.mass = density * 2.0 / 3.0 * M_PI * r * r * h;
  out.com = Eigen::Vector3d(0.0, 3.0 * h / 8.0, 0.0);
  const double across = out.mass * (r * r + h * h) / 5.0 - out.mass * std::pow(3.0 * h / 8.0, 2);
  out.inertia = Eigen::Vector3d(across, 0.4 * out.mass * r * r, across).asDiagonal();
  return out;
}

}  // namespace saltus
