// The optimiser's Hessian band (optim/hessian_band.h) against dense matrices: its entries are the
// band its header describes, each listed once; a Gauss–Newton update equals weight·JᵀJ of the
// local Jacobian written out densely; the band's product is the symmetric matrix's.

#include "saltus/optim/hessian_band.h"

#include <gtest/gtest.h>

#include <random>
#include <set>

namespace saltus {
namespace {

TrajectoryLayout small_layout() {
  TrajectoryLayout layout;
  layout.segment_count = 2;
  layout.keyframe_count = 4;
  layout.set_subdivisions({2, 1, 3});
  return layout;
}

/// Whether (row, column), column <= row, is inside the band: controls at most 3 apart, and any
/// pair with a time variable.
bool in_band(const TrajectoryLayout& layout, int row, int column) {
  const int controls = layout.control_variable_count();
  if (row >= controls || column >= controls) return true;
  return row / layout.curve_block() - column / layout.curve_block() <= 3;
}

TEST(HessianBand, ListsEveryEntryOfTheBandOnce) {
  const TrajectoryLayout layout = small_layout();
  const HessianBand band(layout);
  ASSERT_EQ(band.size(), layout.size());
  std::vector<int> rows(band.nonzeros()), columns(band.nonzeros());
  band.structure(rows.data(), columns.data());
  std::set<std::pair<int, int>> listed;
  for (int e = 0; e < band.nonzeros(); ++e) {
    EXPECT_LE(columns[e], rows[e]);
    EXPECT_TRUE(in_band(layout, rows[e], columns[e])) << rows[e] << "," << columns[e];
    EXPECT_EQ(band.index(rows[e], columns[e]), e);
    EXPECT_EQ(band.index(columns[e], rows[e]), e);
    listed.insert({rows[e], columns[e]});
  }
  EXPECT_EQ(static_cast<int>(listed.size()), band.nonzeros());
  int expected = 0;
  for (int r = 0; r < layout.size(); ++r)
    for (int c = 0; c <= r; ++c)
      expected += in_band(layout, r, c);
  EXPECT_EQ(band.nonzeros(), expected);
}

TEST(HessianBand, GaussNewtonUpdateIsWeightTimesJTransposeJ) {
  const TrajectoryLayout layout = small_layout();
  const HessianBand band(layout);
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  LocalJacobian<4> jac;
  jac.first_control_variable = 2 * layout.curve_block();
  jac.control = Eigen::MatrixXd::Zero(4, 4 * layout.curve_block());
  for (int c = 0; c < jac.control.cols(); c += 2)  // every other column stays zero
    for (int r = 0; r < 4; ++r)
      jac.control(r, c) = u(rng);
  jac.time_count = 2;
  jac.time_variable = {layout.time_variable(1), layout.time_variable(2)};
  for (int s = 0; s < 2; ++s)
    for (int r = 0; r < 4; ++r)
      jac.time(r, s) = u(rng);
  // The same Jacobian written densely.
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(4, layout.size());
  dense.middleCols(jac.first_control_variable, jac.control.cols()) = jac.control;
  for (int s = 0; s < 2; ++s)
    dense.col(jac.time_variable[s]) = jac.time.col(s);
  const Eigen::MatrixXd expected = 0.7 * dense.transpose() * dense;

  std::vector<double> values(band.nonzeros(), 0.0);
  band.add_gauss_newton(jac, 0.7, values.data());
  for (int r = 0; r < layout.size(); ++r)
    for (int c = 0; c <= r; ++c) {
      if (in_band(layout, r, c)) {
        EXPECT_NEAR(values[band.index(r, c)], expected(r, c), 1e-14) << r << "," << c;
      } else {
        EXPECT_EQ(expected(r, c), 0.0) << "outside the band: " << r << "," << c;
      }
    }
}

TEST(HessianBand, QuadraticFormIsThatOfTheSymmetricMatrix) {
  const TrajectoryLayout layout = small_layout();
  const HessianBand band(layout);
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<double> values(band.nonzeros());
  for (double& v : values)
    v = u(rng);
  const int n = layout.size();
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(n, n);
  for (int r = 0; r < n; ++r)
    for (int c = 0; c <= r; ++c)
      if (in_band(layout, r, c)) dense(r, c) = dense(c, r) = values[band.index(r, c)];
  Eigen::VectorXd s(n);
  for (int i = 0; i < n; ++i)
    s[i] = u(rng);
  const double by_hand = s.dot(dense * s);
  EXPECT_NEAR(band.quadratic_form(values, s.data()), by_hand, 1e-12 * (1.0 + std::abs(by_hand)));
}

}  // namespace
}  // namespace saltus
