// The shared constants (base/constants.h) against their definitions: π from the C library,
// gravity pointing down the y axis (docs/method.md: SI units, y up).

#include "saltus/base/constants.h"

#include <gtest/gtest.h>

#include <cmath>

namespace saltus {
namespace {

TEST(Constants, PiAndDegreesAgreeWithTheCLibrary) {
  EXPECT_DOUBLE_EQ(kPi, std::acos(-1.0));
  EXPECT_DOUBLE_EQ(kDegreesPerRadian * std::atan(1.0), 45.0);
  EXPECT_DOUBLE_EQ(degrees_from_radians(std::acos(-1.0)), 180.0);
  EXPECT_DOUBLE_EQ(degrees_from_radians(-std::asin(1.0)), -90.0);
}

TEST(Constants, GravityPointsDownTheYAxis) {
  EXPECT_EQ(gravity(), Eigen::Vector3d(0.0, -kStandardGravity, 0.0));
  EXPECT_DOUBLE_EQ(gravity().norm(), 9.81);
}

}  // namespace
}  // namespace saltus
