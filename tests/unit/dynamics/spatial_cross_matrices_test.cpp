// The cross-product matrices (dynamics/spatial_cross_matrices.h) against spatial.h's cross
// products applied to random vectors: each matrix times a vector is the product it stands for.

#include "saltus/dynamics/spatial_cross_matrices.h"

#include <gtest/gtest.h>

#include <random>

namespace saltus {
namespace {

Vec6<double> random_spatial(std::mt19937& rng) {
  std::normal_distribution<double> normal(0.0, 1.0);
  Vec6<double> v;
  for (int i = 0; i < 6; ++i)
    v[i] = normal(rng);
  return v;
}

TEST(SpatialCrossMatrices, EachIsTheCrossProductItStandsFor) {
  std::mt19937 rng(5);
  for (int trial = 0; trial < 20; ++trial) {
    const Vec6<double> v = random_spatial(rng), m = random_spatial(rng), h = random_spatial(rng);
    const Eigen::Vector3d d = m.head<3>();
    Vec6<double> rotation = Vec6<double>::Zero();  // S·d: a pure rotation
    rotation.head<3>() = d;
    EXPECT_LE((motion_cross_rotation(v) * d - cross_motion(v, rotation)).norm(), 1e-12);
    EXPECT_LE((force_cross_matrix(v) * h - cross_force(v, h)).norm(), 1e-12);
    // δv ↦ δv ×* h, for a fixed h.
    EXPECT_LE((cross_force_by_velocity(h) * m - cross_force(m, h)).norm(), 1e-12);
    Vec6<double> joint_rate = Vec6<double>::Zero();  // S·ω
    joint_rate.head<3>() = v.head<3>();
    EXPECT_LE((joint_rate_cross_matrix(v.head<3>()) * m - cross_motion(joint_rate, m)).norm(),
              1e-12);
  }
}

}  // namespace
}  // namespace saltus
