// SolverOptions::feasibility_checkpoints on problems with known answers: min (x − 3)² subject to
// x² + 1 <= b. With b = 0.5 no x is feasible (the violation is at least 0.5, at x = 0), so a run
// must be stopped at the first checkpoint that asks for less; with b = 2 the optimum is x = 1
// and a checkpoint the run meets on its way must not stop it.

#include <gtest/gtest.h>

#include <cmath>

#include "saltus/optim/ipopt_solver.h"

namespace saltus {
namespace {

class Disk : public Nlp {
 public:
  explicit Disk(double bound) : bound_(bound) {}
  int variable_count() const override { return 1; }
  int constraint_count() const override { return 1; }
  void bounds(double* xl, double* xu, double* gl, double* gu) const override {
    xl[0] = -kUnbounded, xu[0] = kUnbounded, gl[0] = -kUnbounded, gu[0] = bound_;
  }
  void initial_point(double* x) const override { x[0] = 10.0; }
  double objective(const double* x) override { return (x[0] - 3) * (x[0] - 3); }
  void gradient(const double* x, double* g) override { g[0] = 2 * (x[0] - 3); }
  void constraints(const double* x, double* g) override { g[0] = x[0] * x[0] + 1; }
  int jacobian_nonzeros() const override { return 1; }
  void jacobian_structure(int* rows, int* columns) const override { rows[0] = columns[0] = 0; }
  void jacobian_values(const double* x, double* values) override { values[0] = 2 * x[0]; }
  bool has_hessian() const override { return true; }
  int hessian_nonzeros() const override { return 1; }
  void hessian_structure(int* rows, int* columns) const override { rows[0] = columns[0] = 0; }
  void hessian_values(const double*, double sigma, const double* lambda, double* values) override {
    values[0] = 2 * sigma + 2 * lambda[0];
  }

 private:
  double bound_;
};

TEST(FeasibilityCheckpoint, AnInfeasibleRunStopsAtTheCheckpointAndSaysSo) {
  Disk nlp(0.5);
  SolverOptions options;
  options.feasibility_checkpoints = {{1, 0.5}};
  const SolveReport report = solve_with_ipopt(nlp, options);
  EXPECT_EQ(report.status, "stopped_infeasible");
  EXPECT_FALSE(report.solved);
  EXPECT_EQ(report.iterations, 1);
  EXPECT_EQ(report.ipopt_status,
            "stopped early: constraint violation never below 0.5 in 1 iterations");
  ASSERT_EQ(report.x.size(), 1u);
  EXPECT_TRUE(std::isfinite(report.x[0]));
}

TEST(FeasibilityCheckpoint, ARunThatMeetsItsCheckpointsSolves) {
  // x0 = 10 violates x² + 1 <= 2 by 99; Newton comes below 1 within a few iterations.
  Disk nlp(2.0);
  SolverOptions options;
  options.feasibility_checkpoints = {{8, 1.0}, {30, 0.5}};
  const SolveReport report = solve_with_ipopt(nlp, options);
  EXPECT_EQ(report.status, "solved") << report.ipopt_status;
  ASSERT_EQ(report.x.size(), 1u);
  EXPECT_NEAR(report.x[0], 1.0, 1e-6);
  // The same run without checkpoints takes the same path.
  Disk again(2.0);
  const SolveReport free = solve_with_ipopt(again, SolverOptions{});
  EXPECT_EQ(free.iterations, report.iterations);
  EXPECT_EQ(free.x, report.x);
}

TEST(FeasibilityCheckpoint, NoCheckpointsNoEarlyStop) {
  Disk nlp(0.5);
  SolverOptions options;
  options.max_iterations = 40;
  const SolveReport report = solve_with_ipopt(nlp, options);
  EXPECT_NE(report.status, "stopped_infeasible");
  EXPECT_FALSE(report.solved);
}

}  // namespace
}  // namespace saltus
