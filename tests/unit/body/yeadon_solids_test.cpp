// Tests for Yeadon's solids (body/yeadon_solids.h): closed forms (cylinder, cone frustum,
// semi-ellipsoid) and a numerical integration over a grid of the solid itself, an independent
// path for the tapered stadium solid, the antero-posterior one and the semi-ellipsoid.

#include "saltus/body/yeadon_solids.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

namespace saltus {
namespace {

/// Mass, CoM and inertia of the uniform solid {inside(x, y, z)} within the box |x|, |z| <= half,
/// 0 <= y <= h, by the midpoint rule on an n³ grid.
RigidMass ys_grid(double density, double half, double h, int n,
                  const std::function<bool(double, double, double)>& inside) {
  const double dx = 2 * half / n, dy = h / n;
  double mass = 0;
  Eigen::Vector3d first = Eigen::Vector3d::Zero();
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();  // Σ m p pᵀ
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        const Eigen::Vector3d p(-half + (i + 0.5) * dx, (j + 0.5) * dy, -half + (k + 0.5) * dx);
        if (!inside(p.x(), p.y(), p.z())) continue;
        const double dm = density * dx * dy * dx;
        mass += dm;
        first += dm * p;
        second += dm * p * p.transpose();
      }
  RigidMass out;
  out.mass = mass;
  out.com = first / mass;
  const Eigen::Matrix3d spread = second - mass * out.com * out.com.transpose();
  out.inertia = spread.trace() * Eigen::Matrix3d::Identity() - spread;
  return out;
}

/// Inside the stadium of straight half-length t along the long axis and radius r.
bool ys_in_stadium(double along, double across, double t, double r) {
  const double beyond = std::max(0.0, std::abs(along) - t);
  return beyond * beyond + across * across <= r * r;
}

TEST(YeadonSolids, StadiaFromPerimeterAndWidthGiveThemBack) {
  int status = 9;
  const Stadium s = stadium_from_perimeter_width(0.80, 0.30, &status);
  EXPECT_EQ(status, 0);
  EXPECT_NEAR(s.perimeter(), 0.80, 1e-15);
  EXPECT_NEAR(s.width(), 0.30, 1e-15);
  stadium_from_perimeter_width(0.59, 0.30, &status);
  EXPECT_EQ(status, -1);  // p <= 2w: no stadium
  stadium_from_perimeter_width(0.30 * M_PI * 1.01, 0.30, &status);
  EXPECT_EQ(status, 1);  // rounder than a circle
  const Stadium c = circle_from_perimeter(2 * M_PI * 0.05);
  EXPECT_NEAR(c.r, 0.05, 1e-15);
  EXPECT_EQ(c.t, 0.0);
}

TEST(YeadonSolids, ACylinderAndAConeFrustumHaveTheirClosedForms) {
  const double rho = 1000, r = 0.05, h = 0.3;
  Stadium circle;
  circle.r = r;
  const RigidMass cylinder = stadium_solid(rho, circle, circle, h);
  const double m = rho * M_PI * r * r * h;
  EXPECT_NEAR(cylinder.mass, m, 1e-12);
  EXPECT_NEAR(cylinder.com.y(), h / 2, 1e-15);
  EXPECT_NEAR(cylinder.inertia(1, 1), m * r * r / 2, 1e-12);
  EXPECT_NEAR(cylinder.inertia(0, 0), m * (3 * r * r + h * h) / 12, 1e-12);
  EXPECT_NEAR(cylinder.inertia(2, 2), m * (3 * r * r + h * h) / 12, 1e-12);

  Stadium top;
  top.r = 0.02;
  const double volume = M_PI * h / 3 * (r * r + r * top.r + top.r * top.r);
  EXPECT_NEAR(stadium_solid_volume(circle, top, h), volume, 1e-15);
  const RigidMass frustum = stadium_solid(rho, circle, top, h);
  EXPECT_NEAR(frustum.mass, rho * volume, 1e-12);
  // Centroid of a frustum: h (R² + 2Rr + 3r²) / (4 (R² + Rr + r²)) from the wide end.
  const double R = r, q = top.r;
  EXPECT_NEAR(frustum.com.y(), h * (R * R + 2 * R * q + 3 * q * q) / (4 * (R * R + R * q + q * q)),
              1e-15);
  // About the axis: (3/10) m (R⁵ − r⁵) / (R³ − r³).
  EXPECT_NEAR(
      frustum.inertia(1, 1),
      0.3 * frustum.mass * (std::pow(R, 5) - std::pow(q, 5)) / (std::pow(R, 3) - std::pow(q, 3)),
      1e-12);
}

TEST(YeadonSolids, ATaperedStadiumSolidMatchesAGridIntegration) {
  const double rho = 1050, h = 0.2;
  Stadium bottom, top;
  bottom.t = 0.06;
  bottom.r = 0.08;
  top.t = 0.02;
  top.r = 0.05;
  const RigidMass exact = stadium_solid(rho, bottom, top, h);
  const RigidMass grid = ys_grid(rho, 0.15, h, 160, [&](double x, double y, double z) {
    const double u = y / h;
    return ys_in_stadium(x, z, bottom.t + (top.t - bottom.t) * u,
                         bottom.r + (top.r - bottom.r) * u);
  });
  EXPECT_NEAR(exact.mass / grid.mass, 1.0, 2e-3);
  EXPECT_NEAR(exact.com.y(), grid.com.y(), 2e-4);
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(exact.inertia(k, k) / grid.inertia(k, k), 1.0, 5e-3) << k;
  EXPECT_NEAR(stadium_solid_volume(bottom, top, h) * rho, exact.mass, 1e-12);

  // Turned antero-posterior (a heel): its long direction along z.
  Stadium heel = bottom;
  heel.anterior_posterior = true;
  Stadium round;
  round.r = 0.05;
  const RigidMass turned = stadium_solid(rho, heel, round, h);
  const RigidMass turned_grid = ys_grid(rho, 0.15, h, 160, [&](double x, double y, double z) {
    const double u = y / h;
    return ys_in_stadium(z, x, heel.t * (1 - u), heel.r + (round.r - heel.r) * u);
  });
  EXPECT_NEAR(turned.mass / turned_grid.mass, 1.0, 2e-3);
  EXPECT_NEAR(turned.inertia(0, 0) / turned_grid.inertia(0, 0), 1.0, 5e-3);
  EXPECT_NEAR(turned.inertia(2, 2) / turned_grid.inertia(2, 2), 1.0, 5e-3);
  EXPECT_GT(turned.inertia(0, 0), turned.inertia(2, 2));  // long in z: hardest to turn about x
}

TEST(YeadonSolids, ASemiEllipsoidMatchesItsClosedFormAndAGrid) {
  const double rho = 1110, r = 0.09, h = 0.13;
  const RigidMass head = semi_ellipsoid(rho, r, h);
  EXPECT_NEAR(head.mass, rho * 2.0 / 3.0 * M_PI * r * r * h, 1e-12);
  EXPECT_NEAR(head.com.y(), 3 * h / 8, 1e-15);
  const RigidMass grid = ys_grid(rho, r, h, 160, [&](double x, double y, double z) {
    return (x * x + z * z) / (r * r) + y * y / (h * h) <= 1.0;
  });
  EXPECT_NEAR(head.mass / grid.mass, 1.0, 2e-3);
  EXPECT_NEAR(head.com.y(), grid.com.y(), 2e-4);
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(head.inertia(k, k) / grid.inertia(k, k), 1.0, 5e-3) << k;
}

}  // namespace
}  // namespace saltus
