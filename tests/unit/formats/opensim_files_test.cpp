// The OpenSim export's files (formats/opensim_files.h): the coordinates named as
// body/joint_coordinates.h names them after the root's six; their generalised forces do the work
// the wrenches do (Σ τ·q̇ = n·ω + F·v at every joint, the rates by central differences of the
// values); the .mot in degrees and continuous over a twisting flight, the .sto's columns named
// as OpenSim's Inverse Dynamics names them; the .osim holds a body and a CustomJoint per segment
// with Saltus's mass properties. tests/cli/export_opensim_test.cpp reads the files back with an
// independent reader.

#include "saltus/formats/opensim_files.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "saltus/base/text_format.h"
#include "saltus/body/joint_coordinates.h"
#include "saltus/motion/interpolate.h"
#include "support/test_motions.h"

namespace saltus {
namespace {

TEST(OpensimFiles, CoordinatesAreTheRootsSixThenEachJointsThree) {
  const BodyModel model = test::bundled_model();
  const std::vector<OpensimCoordinate> c = opensim_coordinates(model);
  ASSERT_EQ(c.size(), static_cast<std::size_t>(3 * model.size() + 3));
  const char* root[6] = {"somersault", "tilt", "twist", "root_tx", "root_ty", "root_tz"};
  for (int i = 0; i < 6; ++i) {
    EXPECT_EQ(c[i].name, root[i]);
    EXPECT_EQ(c[i].rotational, i < 3);
  }
  for (int k = 1; k < model.size(); ++k)
    for (int i = 0; i < 3; ++i) {
      EXPECT_EQ(c[3 + 3 * k + i].name, joint_coordinates(model, k).coordinates[i].name);
      EXPECT_TRUE(c[3 + 3 * k + i].rotational);
    }
}

TEST(OpensimFiles, GeneralisedForcesDoTheWorkOfTheWrenches) {
  const BodyModel model = test::bundled_model();
  const Trajectory<double> trajectory = motion_trajectory(test::twist_motion(model), model);
  const double h = 1e-6;
  for (double t : {0.3, 0.8, 1.4}) {
    const std::vector<double> times = {t - h, t, t + h};
    std::vector<BodyState<double>> states(3, BodyState<double>(model.size()));
    for (int i = 0; i < 3; ++i)
      trajectory.sample(times[i], states[i]);
    const std::vector<SampleRecord> records = evaluate_states(model, times, states);
    std::vector<OpensimFrame> frames;
    for (int i = 0; i < 3; ++i)
      frames.push_back(opensim_frame(model, states[i], records[i]));
    const Eigen::VectorXd rates = (frames[2].values - frames[0].values) / (2 * h);
    const OpensimFrame& f = frames[1];
    const BodyState<double>& s = states[1];
    const SampleRecord& r = records[1];
    // The root: its rotations and translations against the root wrench (root frame, origin).
    const double root_power = f.forces.head<6>().dot(rates.head<6>());
    const double wrench_power =
        r.root_wrench.tail<3>().dot(s.joints[0].omega) +
        r.root_wrench.head<3>().dot(s.joints[0].q.inverse() * s.root_velocity);
    EXPECT_NEAR(root_power, wrench_power, 1e-5 * (1 + std::abs(wrench_power))) << "t = " << t;
    EXPECT_TRUE(f.values.segment<3>(3).isApprox(s.root_position, 1e-14));
    for (int k = 1; k < model.size(); ++k) {
      const double power = f.forces.segment<3>(3 + 3 * k).dot(rates.segment<3>(3 + 3 * k));
      const double expected = r.joint_wrench[k].tail<3>().dot(s.joints[k].omega);
      EXPECT_NEAR(power, expected, 1e-5 * (1 + std::abs(expected)))
          << model.segments[k].joint << " at t = " << t;
    }
  }
}

/// How many times `piece` occurs in `text`.
std::size_t osim_occurrences(const std::string& text, const std::string& piece) {
  std::size_t n = 0;
  for (std::size_t at = text.find(piece); at != std::string::npos; at = text.find(piece, at + 1))
    ++n;
  return n;
}

/// The rows of a storage file after its header: the column names, then the numbers.
std::vector<std::vector<std::string>> storage_rows(const std::string& text) {
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line) && line != "endheader") {
  }
  std::vector<std::vector<std::string>> rows;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    rows.emplace_back();
    for (std::string f; std::getline(fields, f, '\t');)
      rows.back().push_back(f);
  }
  return rows;
}

TEST(OpensimFiles, TheMotionIsInDegreesAndContinuousTheForcesNamedAsOpensimDoes) {
  const BodyModel model = test::bundled_model();
  const Trajectory<double> trajectory = motion_trajectory(test::twist_motion(model), model);
  std::vector<double> times;
  std::vector<BodyState<double>> states;
  for (int k = 0; k <= 60; ++k) {
    times.push_back(trajectory.duration() * k / 60);
    states.emplace_back(model.size());
    trajectory.sample(times.back(), states.back());
  }
  const std::vector<SampleRecord> records = evaluate_states(model, times, states);
  std::vector<OpensimFrame> frames;
  for (std::size_t k = 0; k < times.size(); ++k)
    frames.push_back(opensim_frame(model, states[k], records[k]));

  const std::string mot = opensim_coordinates_mot(model, times, frames);
  EXPECT_EQ(mot.rfind("Coordinates\nversion=1\nnRows=61\nnColumns=43\ninDegrees=yes\n", 0), 0u);
  const auto rows = storage_rows(mot);
  ASSERT_EQ(rows.size(), times.size() + 1);
  EXPECT_EQ(rows[0][0], "time");
  EXPECT_EQ(rows[0][1], "somersault");
  const std::vector<OpensimCoordinate> c = opensim_coordinates(model);
  double turned = 0;
  for (std::size_t k = 1; k < rows.size(); ++k) {
    ASSERT_EQ(rows[k].size(), c.size() + 1);
    EXPECT_EQ(std::stod(rows[k][0]), times[k - 1]);
    for (std::size_t i = 0; i < c.size(); ++i) {
      const double value = std::stod(rows[k][i + 1]);
      const double radians = frames[k - 1].values[i];
      if (!c[i].rotational) {
        EXPECT_EQ(value, radians);
        continue;
      }
      // Degrees, the same angle up to whole turns, and no jump between rows.
      const double turns = (value - radians * 180 / M_PI) / 360;
      EXPECT_NEAR(turns, std::round(turns), 1e-9) << c[i].name;
      if (k > 1) {
        EXPECT_LT(std::abs(value - std::stod(rows[k - 1][i + 1])), 90.0) << c[i].name;
      }
      if (c[i].name == "twist") turned = std::max(turned, std::abs(turns));
    }
  }
  EXPECT_GE(turned, 1.0) << "the twisting skill's twist goes past a turn, unwrapped";

  const std::string sto = opensim_forces_sto(model, times, frames);
  EXPECT_NE(sto.find("inDegrees=no"), std::string::npos);
  const auto forces = storage_rows(sto);
  EXPECT_EQ(forces[0][1], "somersault_moment");
  EXPECT_EQ(forces[0][4], "root_tx_force");
  EXPECT_EQ(forces[0][7], c[6].name + "_moment");
  EXPECT_EQ(std::stod(forces[3][5]), frames[2].forces[4]);

  frames.pop_back();
  EXPECT_THROW(opensim_coordinates_mot(model, times, frames), std::invalid_argument);
}

TEST(OpensimFiles, TheModelHoldsABodyAndACustomJointPerSegment) {
  BodyModel model = test::bundled_model();
  const int thigh = model.segment_index("thigh_l");
  model.segments[thigh].inertia(1, 2) = model.segments[thigh].inertia(2, 1) = -0.002;
  const std::string osim = opensim_model_xml(model, "tuck <1>");
  EXPECT_EQ(osim.rfind("<?xml version=\"1.0\" encoding=\"UTF-8\" ?>\n<OpenSimDocument "
                       "Version=\"40000\">\n  <Model name=\"tuck &lt;1&gt;\">",
                       0),
            0u);
  EXPECT_NE(osim.find("<gravity>0 -9.81 0</gravity>"), std::string::npos);
  EXPECT_EQ(osim_occurrences(osim, "<Body "), static_cast<std::size_t>(model.size()));
  EXPECT_EQ(osim_occurrences(osim, "<CustomJoint "), static_cast<std::size_t>(model.size()));
  const Segment& s = model.segments[thigh];
  const std::size_t body = osim.find("<Body name=\"" + s.name + "\">");
  ASSERT_NE(body, std::string::npos);
  EXPECT_LT(osim.find("<mass>" + exact_number(s.mass) + "</mass>", body),
            osim.find("</Body>", body));
  EXPECT_NE(osim.find("<inertia>0.2 0.041 0.19 0 0 -0.002</inertia>", body), std::string::npos)
      << "Ixx Iyy Izz Ixy Ixz Iyz, the matrix's entries";
  // The hip's flexion turns against the Cardan angle: about the thigh's −x axis, slope +1.
  const std::size_t hip = osim.find("<CustomJoint name=\"hip_l\">");
  ASSERT_NE(hip, std::string::npos);
  const std::size_t flexion = osim.find("<TransformAxis name=\"rotation1\">\n", hip);
  ASSERT_NE(flexion, std::string::npos);
  EXPECT_EQ(osim.find("<coordinates>hip_flexion_l</coordinates>", hip),
            osim.find("<coordinates>", flexion));
  EXPECT_EQ(osim.find("<axis>-1 0 0</axis>", hip), osim.find("<axis>", flexion));
  // Every function of a coordinate has slope +1: OpenSim 4.0 reads no other as a rotation.
  const std::size_t linear_functions = osim_occurrences(osim, "<LinearFunction ");
  EXPECT_EQ(linear_functions, static_cast<std::size_t>(3 * model.size() + 3));
  EXPECT_EQ(osim_occurrences(osim, "<coefficients>1 "), linear_functions);
}

}  // namespace
}  // namespace saltus
