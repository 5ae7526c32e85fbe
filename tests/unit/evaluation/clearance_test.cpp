// Clearances and entry by independent paths: a rigid standing body placed at a known distance
// from the platform's edge or moved into the platform's space, or standing on the trampoline's
// bed, checked against distances worked out here face by face; the bundled dive and M1 against a
// brute-force search on a grid ten times finer than the written trajectory's; the dive's entry
// against a bisection of its first contact with the water.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "saltus/evaluation/apparatus.h"
#include "saltus/evaluation/clearance.h"
#include "saltus/evaluation/evaluate.h"
#include "saltus/formats/motion_file.h"
#include "support/test_motions.h"

namespace saltus {
namespace {

/// Every body point of a sample: segment origins and shape ends, world.
std::vector<Eigen::Vector3d> points_of(const BodyModel& model, const SampleRecord& s) {
  std::vector<Eigen::Vector3d> out;
  for (std::size_t i = 0; i < model.segments.size(); ++i) {
    out.push_back(s.segment_position[i]);
    out.push_back(s.segment_position[i] +
                  s.segment_rotation[i] * Eigen::Vector3d(0, model.segments[i].shape.length, 0));
  }
  return out;
}

SampleRecord standing_at(const BodyModel& model, const Eigen::Vector3d& root) {
  BodyState<double> standing(model.size());
  standing.root_position = root;
  return evaluate_states(model, {0.0}, {standing}).front();
}

/// A platform 5 m above the water, leaving towards +z from the origin: its edge at z = 0.15.
Apparatus five_metre_platform() {
  Apparatus a;
  a.kind = ApparatusKind::kPlatform;
  a.takeoff_height = 5.0;
  a.landing_height = 0.0;
  a.takeoff_point = Eigen::Vector3d(0, 5.0, 0);
  a.direction = Eigen::Vector3d::UnitZ();
  return a;
}

TEST(Clearance, ABodyAheadOfThePlatformIsItsDistanceFromTheEdge) {
  const BodyModel model = test::bundled_model();
  const Apparatus platform = five_metre_platform();
  // Place the standing body so that its rearmost point is 0.4 m ahead of the edge and its
  // highest point 1 m below the top: the front face is the nearest, 0.4 m away.
  SampleRecord s = standing_at(model, Eigen::Vector3d::Zero());
  double rear = std::numeric_limits<double>::infinity(), top = -rear;
  for (const Eigen::Vector3d& p : points_of(model, s)) {
    rear = std::min(rear, p.z());
    top = std::max(top, p.y());
  }
  s = standing_at(model, Eigen::Vector3d(0, 4.0 - top, kPlatformEdgeAhead + 0.4 - rear));
  const ApparatusClearance c = apparatus_clearance(model, platform, {s});
  EXPECT_EQ(c.kind, ApparatusKind::kPlatform);
  EXPECT_NEAR(c.min_distance_m, 0.4, 1e-12);
  EXPECT_NEAR(c.edge_m, -0.4, 1e-12);
  EXPECT_GE(c.vertical_m, 1.0 - 1e-12);
  EXPECT_FALSE(c.collision);
  EXPECT_EQ(c.distance.size(), 1u);
  EXPECT_DOUBLE_EQ(c.distance.front(), c.min_distance_m);
  EXPECT_FALSE(c.point.empty());
}

TEST(Clearance, ABodyAboveThePlatformIsItsHeightAboveTheTop) {
  const BodyModel model = test::bundled_model();
  SampleRecord s = standing_at(model, Eigen::Vector3d::Zero());
  const double lowest = lowest_body_point(model, s);
  // Over the platform, well behind the edge: the top face is the nearest, 0.3 m below the feet.
  s = standing_at(model, Eigen::Vector3d(0, 5.3 - lowest, -2.0));
  const ApparatusClearance c = apparatus_clearance(model, five_metre_platform(), {s});
  EXPECT_NEAR(c.min_distance_m, 0.3, 1e-12);
  EXPECT_NEAR(c.vertical_m, -0.3, 1e-12);
  EXPECT_FALSE(c.collision);
}

TEST(Clearance, ABodyInsideThePlatformsSpaceIsACollision) {
  const BodyModel model = test::bundled_model();
  // 0.5 m behind the edge and 2 m below the top: every point is in the tower's space; the depth
  // of each is its distance to the nearest face (top, front, sides, water, back).
  const SampleRecord s = standing_at(model, Eigen::Vector3d(0, 2.0, kPlatformEdgeAhead - 0.5));
  double deepest = 0.0;
  for (const Eigen::Vector3d& p : points_of(model, s)) {
    const double depth = std::min({5.0 - p.y(), p.y(), kPlatformEdgeAhead - p.z(),
                                   p.z() - (kPlatformEdgeAhead - kPlatformLength),
                                   0.5 * kPlatformWidth - std::abs(p.x())});
    ASSERT_GT(depth, 0.0);
    deepest = std::max(deepest, depth);
  }
  const ApparatusClearance c = apparatus_clearance(model, five_metre_platform(), {s});
  EXPECT_TRUE(c.collision);
  EXPECT_NEAR(c.min_distance_m, -deepest, 1e-12);
  EXPECT_GT(c.edge_m, 0.0);
  EXPECT_GT(c.vertical_m, 0.0);
}

/// Horizontal distance of (x, z) from the trampoline frame's ring, by cases.
double ring_distance(double x, double z) {
  x = std::abs(x);
  z = std::abs(z);
  const double bx = 0.5 * kBedWidth, bz = 0.5 * kBedLength;
  const double fx = 0.5 * kFrameWidth, fz = 0.5 * kFrameLength;
  if (x < bx && z < bz) return std::min(bx - x, bz - z);  // over the bed: to its edge
  if (x <= fx && z <= fz) return 0.0;                     // over the frame
  return std::hypot(std::max(x - fx, 0.0), std::max(z - fz, 0.0));
}

/// Distance from the frame of a point above the frame's top.
double frame_distance(const Eigen::Vector3d& p) {
  EXPECT_GT(p.y(), kFrameTop);
  return std::hypot(ring_distance(p.x(), p.z()), p.y() - kFrameTop);
}

Apparatus trampoline_at_origin() {
  Apparatus a;
  a.takeoff_point = Eigen::Vector3d::Zero();
  a.direction = Eigen::Vector3d::UnitZ();
  return a;
}

TEST(Clearance, ABodyOnTheBedIsItsDistanceFromTheFrame) {
  const BodyModel model = test::bundled_model();
  SampleRecord s = standing_at(model, Eigen::Vector3d::Zero());
  const double lowest = lowest_body_point(model, s);
  // Feet on the bed, 0.6 m off its long axis: the side edge is near.
  s = standing_at(model, Eigen::Vector3d(0.6, -lowest, 0.2));
  double expected = std::numeric_limits<double>::infinity();
  for (const Eigen::Vector3d& p : points_of(model, s))
    expected = std::min(expected, frame_distance(p));
  const ApparatusClearance c = apparatus_clearance(model, trampoline_at_origin(), {s});
  EXPECT_EQ(c.kind, ApparatusKind::kTrampoline);
  EXPECT_NEAR(c.min_distance_m, expected, 1e-12);
  EXPECT_GT(c.edge_m, 0.0);  // over the bed
  EXPECT_FALSE(c.collision);
}

TEST(Clearance, AFootThroughTheFrameIsACollision) {
  const BodyModel model = test::bundled_model();
  SampleRecord s = standing_at(model, Eigen::Vector3d::Zero());
  const double lowest = lowest_body_point(model, s);
  // The feet's ends 2 cm into the frame's 6 cm, the body over its side (between bed and pads).
  const double x = 0.25 * (kBedWidth + kFrameWidth);
  s = standing_at(model, Eigen::Vector3d(x, kFrameTop - 0.02 - lowest, 0.0));
  const ApparatusClearance c = apparatus_clearance(model, trampoline_at_origin(), {s});
  EXPECT_TRUE(c.collision);
  EXPECT_LT(c.min_distance_m, 0.0);
  EXPECT_LT(c.edge_m, 0.0);  // beyond the bed's edge
}

struct Flight {
  MotionFile file;
  MotionEvaluation evaluation;
  Apparatus apparatus;
};

Flight evaluate_flight(const std::string& name) {
  Flight out{
      load_motion_file(std::string(SALTUS_EXAMPLES_DIR) + "/motions/" + name + ".motion.json"),
      {},
      {}};
  out.evaluation = evaluate_motion(out.file.motion, out.file.model);
  out.apparatus = apparatus_for(out.file.model, out.file.motion.takeoff, out.evaluation.samples);
  return out;
}

/// The closest pass from `from` on, by brute force on a grid ten times finer, through the
/// platform's faces or the frame worked out above.
double brute_force_clearance(const Flight& f, double from, int per_sample) {
  const std::vector<SampleRecord>& samples = f.evaluation.samples;
  const double duration = samples.back().time;
  const int count = (static_cast<int>(samples.size()) - 1) * per_sample + 1;
  std::vector<double> times;
  for (double t : uniform_times(duration, count))
    if (t >= from - 1e-12) times.push_back(t);
  const std::vector<SampleRecord> dense =
      evaluate_trajectory(f.file.model, f.evaluation.trajectory, times);
  const Eigen::Affine3d to_local = world_from_apparatus(f.apparatus).inverse();
  const double top = f.apparatus.takeoff_height - f.apparatus.landing_height;
  double best = std::numeric_limits<double>::infinity();
  for (const SampleRecord& s : dense)
    for (const Eigen::Vector3d& world : points_of(f.file.model, s)) {
      const Eigen::Vector3d p = to_local * world;
      double d = 0.0;
      if (f.apparatus.kind == ApparatusKind::kTrampoline) {
        d = frame_distance(p);
      } else {
        // Outside the tower's space: the distance to its nearest face, edge or corner.
        const double dz = std::max(p.z() - kPlatformEdgeAhead, 0.0);
        const double dy = std::max(p.y(), 0.0);
        const double dx = std::max(std::abs(p.x()) - 0.5 * kPlatformWidth, 0.0);
        d = std::sqrt(dx * dx + dy * dy + dz * dz);
        if (d == 0.0)
          d = -std::min({kPlatformEdgeAhead - p.z(), -p.y(), p.y() + top,
                         0.5 * kPlatformWidth - std::abs(p.x())});
      }
      best = std::min(best, d);
    }
  return best;
}

TEST(Clearance, TheBundledDivePassesThePlatformAsABruteForceSearchSays) {
  const Flight dive = evaluate_flight("dive-5m-front-one-and-a-half-twists");
  ASSERT_EQ(dive.apparatus.kind, ApparatusKind::kPlatform);
  const ApparatusClearance c =
      apparatus_clearance(dive.file.model, dive.apparatus, dive.evaluation.samples);
  // The search starts at the CoM's apex.
  double apex = 0.0, highest = -1e9;
  for (const SampleRecord& s : dive.evaluation.samples)
    if (s.com.y() > highest) {
      highest = s.com.y();
      apex = s.time;
    }
  EXPECT_DOUBLE_EQ(c.from_s, apex);
  // On the written samples the same as brute force on them; on a grid ten times finer no more
  // than 1 cm nearer.
  EXPECT_NEAR(c.min_distance_m, brute_force_clearance(dive, apex, 1), 1e-9);
  const double fine = brute_force_clearance(dive, apex, 10);
  EXPECT_LE(fine, c.min_distance_m + 1e-12);
  EXPECT_NEAR(fine, c.min_distance_m, 0.01);
  EXPECT_EQ(c.collision, c.min_distance_m < 0.0);
  EXPECT_GE(c.time_s, apex);
  EXPECT_EQ(c.distance.size(), dive.evaluation.samples.size());
  std::printf(
      "dive clearance %.3f m at %.3f s: %s, %.3f m behind the edge, %.3f m below the top%s\n",
      c.min_distance_m, c.time_s, c.point.c_str(), c.edge_m, c.vertical_m,
      c.collision ? " (in the platform's space)" : "");
}

TEST(Clearance, TheTrampolineSkillKeepsClearOfTheFrame) {
  const Flight m1 = evaluate_flight("M1-straight-back-somersault");
  ASSERT_EQ(m1.apparatus.kind, ApparatusKind::kTrampoline);
  const ApparatusClearance c =
      apparatus_clearance(m1.file.model, m1.apparatus, m1.evaluation.samples);
  EXPECT_DOUBLE_EQ(c.from_s, 0.0);
  EXPECT_NEAR(c.min_distance_m, brute_force_clearance(m1, 0.0, 1), 1e-9);
  EXPECT_FALSE(c.collision);
  // Taking off from the middle of the bed: the nearest the frame can be is about the bed's half
  // width, 1.07 m, less the body's own half width.
  EXPECT_GT(c.min_distance_m, 0.5);
  EXPECT_LT(c.min_distance_m, 0.5 * kBedWidth + 0.1);
  EXPECT_FALSE(dive_entry(m1.file.model, m1.apparatus, m1.evaluation.samples).has_value());
}

/// Body line of a sample (feet's ends to the head), worked out here.
Eigen::Vector3d line_of(const BodyModel& model, const SampleRecord& s) {
  const std::vector<Eigen::Vector3d> p = points_of(model, s);
  const auto end = [&](const char* name) {
    return p[2 * static_cast<std::size_t>(model.segment_index(name)) + 1];
  };
  return end("thorax") - 0.5 * (end("foot_l") + end("foot_r"));
}

TEST(Clearance, TheDivesEntryIsWhereItsFirstContactReachesTheWater) {
  const Flight dive = evaluate_flight("dive-5m-front-one-and-a-half-twists");
  const BodyModel& model = dive.file.model;
  const auto entry = dive_entry(model, dive.apparatus, dive.evaluation.samples);
  ASSERT_TRUE(entry.has_value());
  // Bisection on the trajectory for the time the lowest point reaches the water.
  const double water = dive.apparatus.landing_height;
  const auto lowest_at = [&](double t) {
    return lowest_body_point(model, evaluate_trajectory(model, dive.evaluation.trajectory, {t})[0]);
  };
  double lo = dive.evaluation.samples.front().time, hi = dive.evaluation.samples.back().time;
  ASSERT_LE(lowest_at(hi), water + 1e-12);
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (lowest_at(mid) > water ? lo : hi) = mid;
  }
  // Linear interpolation between samples 20 ms apart: within a few ms of the true contact.
  EXPECT_NEAR(entry->time_s, hi, 0.005);
  const SampleRecord at =
      evaluate_trajectory(model, dive.evaluation.trajectory, {entry->time_s})[0];
  const Eigen::Vector3d line = line_of(model, at);
  const double angle = std::acos(std::abs(line.y()) / line.norm()) * 180.0 / M_PI;
  EXPECT_NEAR(entry->angle_to_vertical_deg, angle, 1.0);
  EXPECT_EQ(entry->head_first, line.y() < 0.0);
  EXPECT_EQ(entry->vertical, entry->angle_to_vertical_deg <= kVerticalEntryToleranceDeg);
  EXPECT_NEAR(entry->com_height_m, at.com.y() - water, 0.01);
  EXPECT_GT(entry->com_height_m, 0.3);  // the CoM is still above the water at first contact
  std::printf("dive entry at %.3f s: %s first, %.1f deg from vertical, %s, CoM %.2f m up\n",
              entry->time_s, entry->first_contact.c_str(), entry->angle_to_vertical_deg,
              entry->head_first ? "head first" : "feet first", entry->com_height_m);
}

}  // namespace
}  // namespace saltus
