// docs/testing.md: the residual that inverse dynamics reports (res_* columns) must equal
// dP/dt − m·g and dL_G/dt computed from the exported segment poses alone, by finite differences:
// a code path that shares nothing with the recursive Newton-Euler algorithm.

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "saltus/body/body_model.h"
#include "saltus/formats/model_file.h"
#include "saltus/formats/trajectory_csv.h"
#include "support/cli_runner.h"

namespace saltus {
namespace {

struct Poses {
  std::vector<double> t;
  std::vector<std::vector<Eigen::Vector3d>> com;      // [sample][segment] segment CoM, world
  std::vector<std::vector<Eigen::Quaterniond>> rot;   // [sample][segment] world_from_segment
  std::vector<Eigen::Matrix<double, 6, 1>> residual;  // res_* columns
};

Poses read_poses(const std::string& csv_path, const BodyModel& model) {
  const CsvTable table = read_csv_table(csv_path);
  Poses p;
  for (const auto& row : table.rows) {
    p.t.push_back(row[table.column("t")]);
    std::vector<Eigen::Vector3d> com;
    std::vector<Eigen::Quaterniond> rot;
    for (const Segment& s : model.segments) {
      const int c = table.column(s.name + ".x");
      const Eigen::Vector3d origin(row[c], row[c + 1], row[c + 2]);
      const Eigen::Quaterniond q(row[c + 3], row[c + 4], row[c + 5], row[c + 6]);
      rot.push_back(q.normalized());
      com.push_back(origin + q.normalized() * s.com);
    }
    p.com.push_back(com);
    p.rot.push_back(rot);
    Eigen::Matrix<double, 6, 1> r;
    const int c = table.column("res_fx");
    for (int i = 0; i < 6; ++i)
      r[i] = row[c + i];
    p.residual.push_back(r);
  }
  return p;
}

TEST(ResidualFromPoses, MatchesFiniteDifferencesOfMomentum) {
  test::TempDir dir;
  const std::string out = dir / "out";
  // 2041 samples on 2.04 s: h = 1 ms.
  const auto run =
      test::run_cli("evaluate " + test::m1_path() + " --out " + out + " --samples 2041");
  ASSERT_EQ(run.status, 0) << run.output;
  const BodyModel model = load_body_model(out + "/model.json");
  const Poses p = read_poses(out + "/trajectory.csv", model);
  const int n = static_cast<int>(p.t.size());
  const double h = p.t[1] - p.t[0];
  const double mass = model.total_mass();

  // Momenta at samples 1..n-2 by central differences of the poses.
  std::vector<Eigen::Vector3d> linear(n), angular(n);
  for (int k = 1; k + 1 < n; ++k) {
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (int s = 0; s < model.size(); ++s)
      c += model.segments[s].mass * p.com[k][s];
    c /= mass;
    linear[k].setZero();
    angular[k].setZero();
    for (int s = 0; s < model.size(); ++s) {
      const Segment& seg = model.segments[s];
      const Eigen::Vector3d v = (p.com[k + 1][s] - p.com[k - 1][s]) / (2 * h);
      Eigen::Quaterniond before = p.rot[k - 1][s], after = p.rot[k + 1][s];
      const Eigen::Quaterniond& now = p.rot[k][s];
      if (before.coeffs().dot(now.coeffs()) < 0) before.coeffs() *= -1;
      if (after.coeffs().dot(now.coeffs()) < 0) after.coeffs() *= -1;
      Eigen::Quaterniond qdot;
      qdot.coeffs() = (after.coeffs() - before.coeffs()) / (2 * h);
      const Eigen::Vector3d omega_world = 2.0 * (qdot * now.conjugate()).vec();
      const Eigen::Matrix3d r = now.toRotationMatrix();
      linear[k] += seg.mass * v;
      angular[k] +=
          seg.mass * (p.com[k][s] - c).cross(v) + r * seg.inertia * r.transpose() * omega_world;
    }
  }

  double max_residual = 0, max_error_force = 0, max_error_moment = 0;
  const Eigen::Vector3d weight_term = mass * Eigen::Vector3d(0, -9.81, 0);
  // The spline is C² but its jerk jumps at the knots (the keyframe times here), where the
  // differences' truncation error is O(h·Δjerk) instead of O(h²): skip a few samples around them.
  std::ifstream result_file(out + "/result.json");
  const std::vector<double> knots =
      nlohmann::json::parse(result_file)["keyframe_times_before"].get<std::vector<double>>();
  auto near_knot = [&](double t) {
    for (double knot : knots)
      if (std::abs(t - knot) < 3.5 * h) return true;
    return false;
  };
  int compared = 0;
  for (int k = 2; k + 2 < n; ++k) {
    if (near_knot(p.t[k])) continue;
    ++compared;
    const Eigen::Vector3d force = (linear[k + 1] - linear[k - 1]) / (2 * h) - weight_term;
    const Eigen::Vector3d moment = (angular[k + 1] - angular[k - 1]) / (2 * h);
    max_residual = std::max(max_residual, p.residual[k].norm());
    max_error_force = std::max(max_error_force, (force - p.residual[k].head<3>()).norm());
    max_error_moment = std::max(max_error_moment, (moment - p.residual[k].tail<3>()).norm());
  }
  // The motion is far from free flight (tens of newtons) yet both paths agree to a fraction of a
  // percent: what remains is the O(h²) truncation error of the differences.
  EXPECT_GT(compared, 2000);
  EXPECT_GT(max_residual, 10.0);
  EXPECT_LT(max_error_force, 1e-4 * max_residual) << "max residual " << max_residual;
  EXPECT_LT(max_error_moment, 1e-4 * max_residual) << "max residual " << max_residual;
  RecordProperty("max_residual", std::to_string(max_residual));
  std::printf("max |res| %.3f, max FD error force %.2e N, moment %.2e N·m\n", max_residual,
              max_error_force, max_error_moment);
}

}  // namespace
}  // namespace saltus
