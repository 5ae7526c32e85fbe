// The scalar helpers (math/scalar.h) that let one templated code run on doubles and on AD scalars:
// atan2_same_type's value in every quadrant and its derivative (x·dy − y·dx)/(x² + y²) by finite
// differences, including AD scalars that carry no derivative vector at all.

#include "saltus/math/scalar.h"

#include <gtest/gtest.h>

#include <cmath>

namespace saltus {
namespace {

using AdTwo = Eigen::AutoDiffScalar<Eigen::Vector2d>;
using AdDynamic = Eigen::AutoDiffScalar<Eigen::VectorXd>;

TEST(Scalar, ValueOfAndConstantStripAndCarryNoDerivative) {
  EXPECT_EQ(value_of(2.5), 2.5);
  EXPECT_EQ(value_of(AdTwo(2.5, 2, 0)), 2.5);
  const AdTwo c = constant<AdTwo>(4.0);
  EXPECT_EQ(c.value(), 4.0);
  EXPECT_TRUE(c.derivatives().size() == 0 || c.derivatives().isZero());
}

TEST(Atan2SameType, ValueAndDerivativesMatchInEveryQuadrant) {
  const double h = 1e-7;
  for (double y : {0.7, -0.7, 1e-3, -2.0}) {
    for (double x : {1.3, -1.3, -1e-3, 0.4}) {
      EXPECT_EQ(atan2_same_type(y, x), std::atan2(y, x));
      const AdTwo a = atan2_same_type(AdTwo(y, 2, 0), AdTwo(x, 2, 1));
      EXPECT_EQ(a.value(), std::atan2(y, x));
      const double dy = (std::atan2(y + h, x) - std::atan2(y - h, x)) / (2 * h);
      const double dx = (std::atan2(y, x + h) - std::atan2(y, x - h)) / (2 * h);
      EXPECT_NEAR(a.derivatives()[0], dy, 1e-6 * (1 + std::abs(dy))) << y << "," << x;
      EXPECT_NEAR(a.derivatives()[1], dx, 1e-6 * (1 + std::abs(dx))) << y << "," << x;
    }
  }
}

TEST(Atan2SameType, AnEmptyDerivativeVectorCountsAsZero) {
  // Dynamic AD constants have no derivative entries; the other argument's alone must come out.
  const double y = 0.3, x = -1.1, r2 = x * x + y * y;
  AdDynamic with_y(y, 2, 0), with_x(x, 2, 1);
  const AdDynamic only_y = atan2_same_type(with_y, AdDynamic(x));
  ASSERT_EQ(only_y.derivatives().size(), 2);
  EXPECT_NEAR(only_y.derivatives()[0], x / r2, 1e-15);
  EXPECT_EQ(only_y.derivatives()[1], 0.0);
  const AdDynamic only_x = atan2_same_type(AdDynamic(y), with_x);
  ASSERT_EQ(only_x.derivatives().size(), 2);
  EXPECT_EQ(only_x.derivatives()[0], 0.0);
  EXPECT_NEAR(only_x.derivatives()[1], -y / r2, 1e-15);
}

}  // namespace
}  // namespace saltus
