// The bundled real captures (examples/captures/README.md): the facts that README states,
// measured independently of Saltus, and a hand conversion of the DeepMimic clip made with
// another tool.

#include <gtest/gtest.h>

#include <filesystem>
#include <regex>

#include "saltus/formats/motion_file.h"
#include "saltus/math/quaternion.h"
#include "saltus/use_cases/captures.h"

namespace saltus {
namespace {

std::string bundled_capture(const std::string& name) {
  return std::string(SALTUS_CAPTURES_DIR) + "/" + name;
}

CaptureFile import(const std::string& name, const CaptureFileOptions& options = {}) {
  return import_capture_file(bundled_capture(name), options);
}

TEST(RealCaptures, TheTwoDeepMimicFilesImportToTheSameMotion) {
  // y up, cm, facing +x, Z-X-Y, DeepMimic names; and z up, metres, facing −y, X-Y-Z, a T-pose
  // rest, Mixamo/CMU-style names, legs first.
  const CaptureFile a = import("deepmimic-backflip.bvh");
  const CaptureFile b = import("deepmimic-backflip-zup.bvh");
  EXPECT_EQ(a.import.retargeting.mapping.convention, "DeepMimic");
  EXPECT_EQ(b.import.retargeting.axes.up_name, "+z");
  EXPECT_EQ(b.import.retargeting.axes.unit, "m");
  ASSERT_EQ(a.import.flight.first_frame, b.import.flight.first_frame);
  ASSERT_EQ(a.import.flight.last_frame, b.import.flight.last_frame);
  double worst = 0.0;
  for (std::size_t f = 0; f < a.import.frames.size(); ++f)
    for (std::size_t s = 0; s < a.import.frames[f].joint_rotation.size(); ++s)
      worst = std::max(worst, rotation_angle_between(a.import.frames[f].joint_rotation[s],
                                                     b.import.frames[f].joint_rotation[s]));
  std::printf("DeepMimic, two files: largest joint rotation difference %.3g rad\n", worst);
  EXPECT_LT(worst, 1e-4);
  EXPECT_LT((a.import.takeoff_fit.velocity - b.import.takeoff_fit.velocity).norm(), 1e-4);
  EXPECT_EQ(a.import.pick.frames, b.import.pick.frames);
}

TEST(RealCaptures, DeepMimicFlightPhaseAndSomersault) {
  const CaptureFile c = import("deepmimic-backflip.bvh");
  const CaptureImport& im = c.import;
  std::printf(
      "DeepMimic: frames %d-%d, lift-off %.3f s, touch-down %.3f s, somersault %.1f deg in the "
      "flight, %.1f deg in the clip, implied gravity %.2f m/s2, L (%.1f, %.1f, %.1f)\n",
      im.flight.first_frame, im.flight.last_frame, im.flight.liftoff_time, im.flight.touchdown_time,
      im.somersault_flight_deg, im.somersault_clip_deg, im.implied_gravity,
      im.angular_momentum.mean.x(), im.angular_momentum.mean.y(), im.angular_momentum.mean.z());
  // README: airborne frames 11-18, lift-off ≈ 0.665 s, touch-down ≈ 1.181 s; the trunk turns
  // about −219° in the flight and −360° over the clip.
  EXPECT_EQ(im.flight.method, "feet");
  EXPECT_EQ(im.flight.first_frame, 11);
  EXPECT_EQ(im.flight.last_frame, 18);
  EXPECT_NEAR(im.flight.liftoff_time, 0.665, 0.05);
  EXPECT_NEAR(im.flight.touchdown_time, 1.181, 0.05);
  EXPECT_NEAR(im.somersault_flight_deg, -219.0, 10.0);
  EXPECT_NEAR(im.somersault_clip_deg, -360.0, 10.0);
  // A backward somersault about the body's left axis, x after the heading turn.
  EXPECT_LT(im.angular_momentum.mean.x(), -20.0);
  EXPECT_LT(std::abs(im.angular_momentum.mean.z()), 1e-6);
  EXPECT_FALSE(im.suggested_frame_time.has_value());
}

TEST(RealCaptures, DeepMimicMatchesAnIndependentHandConversion) {
  // deepmimic-backflip.motion.json was converted with another tool (chest split half on lumbar
  // and thoracic, neck dropped, the foot's rest as neutral), 6 of the airborne frames.
  const CaptureFile c = import("deepmimic-backflip.bvh");
  const MotionFile hand = load_motion_file(bundled_capture("deepmimic-backflip.motion.json"));
  const Motion& captured = c.import.captured;
  double worst = 0.0;
  for (const Keyframe& k : hand.motion.keyframes) {
    const auto frame = std::lround(k.time / c.import.frame_time);
    ASSERT_LT(static_cast<std::size_t>(frame), captured.keyframes.size());
    const Keyframe& ours = captured.keyframes[frame];
    // The hand conversion did not turn the heading; ours turned it by heading_yaw_deg.
    for (int s = 1; s < c.model.size(); ++s)
      worst = std::max(worst, rotation_angle_between(ours.rotations[s], k.rotations[s]));
  }
  std::printf("DeepMimic vs the hand conversion: largest joint rotation difference %.3g rad\n",
              worst);
  EXPECT_LT(worst, 2e-5);  // the hand conversion prints 6 decimals
  // The take-off CoM state from the same kind of fit (its horizontal velocity not yet turned).
  EXPECT_NEAR(c.import.takeoff_fit.position.y(), hand.motion.takeoff.com_position.y(), 1e-3);
  EXPECT_NEAR(c.import.takeoff_fit.velocity.y(), hand.motion.takeoff.com_velocity.y(), 1e-3);
}

TEST(RealCaptures, MassNamesTheFrameTimeThatMakesItsFlightBallistic) {
  const CaptureFile c = import("mass-backflip.bvh");
  const CaptureImport& im = c.import;
  EXPECT_EQ(im.retargeting.mapping.convention, "MotionBuilder");
  // README: airborne frames 44-76 at the stated rate, −205° of somersault in the flight.
  EXPECT_NEAR(im.flight.first_frame, 44, 1);
  EXPECT_NEAR(im.flight.last_frame, 76, 1);
  EXPECT_NEAR(im.somersault_flight_deg, -205.0, 10.0);
  EXPECT_NEAR(im.somersault_clip_deg, -353.0, 10.0);
  // The performer faces −z although the rest pose faces +z: the heading turns half a turn.
  EXPECT_NEAR(std::abs(im.heading_yaw_deg), 180.0, 10.0);
  // README: at the stated 120 Hz the CoM falls at 40-60 m/s².
  EXPECT_GT(im.implied_gravity, 35.0);
  ASSERT_TRUE(im.suggested_frame_time.has_value());
  std::string warning;
  for (const std::string& w : im.warnings)
    if (w.find("frame time") != std::string::npos) warning = w;
  std::smatch match;
  ASSERT_TRUE(std::regex_search(warning, match, std::regex("--frame-time ([0-9.]+)"))) << warning;
  const double suggested = std::stod(match[1]);
  std::printf("MASS: implied gravity %.1f m/s2 at the stated %.5f s; suggested %.5f s (%.1f Hz)\n",
              im.implied_gravity, im.frame_time, suggested, 1.0 / suggested);

  CaptureFileOptions options;
  options.import.frame_time = suggested;
  const CaptureFile again = import("mass-backflip.bvh", options);
  std::printf("MASS at %.5f s per frame: implied gravity %.2f m/s2, frames %d-%d\n", suggested,
              again.import.implied_gravity, again.import.flight.first_frame,
              again.import.flight.last_frame);
  EXPECT_NEAR(again.import.implied_gravity, 9.81, 0.15 * 9.81);
  EXPECT_FALSE(again.import.suggested_frame_time.has_value());
}

}  // namespace
}  // namespace saltus
