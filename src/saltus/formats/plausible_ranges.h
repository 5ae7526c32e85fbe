#pragma once
/// @file
/// What the model and motion readers accept as physically plausible for a human in flight, in
/// one place. Each bound is an order of magnitude or more beyond what people do, so that no real
/// motion is refused, while numbers that are typos, garbage or attacks (1e308, 1e-320) are
/// refused with a message naming the field instead of turning into NaN downstream.

#include <cstddef>

#include "saltus/base/number_bound.h"

namespace saltus::plausible {

// Body model (docs/formats.md, "Body model").
/// kg per segment. A hand is 0.4 kg; a heavy athlete's thorax 35 kg.
inline constexpr double kMinSegmentMass = 1e-3;
inline constexpr double kMaxSegmentMass = 1e3;
/// m: |joint_position|, |com| and shape sizes per coordinate. Human segments are under 1 m.
inline constexpr double kMaxSegmentLength = 10.0;
/// Segments of a body model: a human model has a few dozen; every verb's cost grows with them
/// (a 200-segment model took 61 s and 1.6 GB to optimise, 1000 ended in bad_alloc).
inline constexpr std::size_t kMaxSegments = 64;
/// m: radius of gyration sqrt(I/m) of each principal moment. A thigh's is about 0.06-0.15 m.
inline constexpr double kMinRadiusOfGyration = 1e-4;
inline constexpr double kMaxRadiusOfGyration = 10.0;
/// Relative slack of the triangle inequality of principal moments (Ia + Ib >= Ic; equality
/// for a flat body) that rounding of printed numbers may need.
inline constexpr double kInertiaTriangleSlack = 1e-6;

// A person to model (`saltus model new`, `model scale`; docs/cli.md, "model").
/// m: standing height. The shortest adults are about 0.6 m, the tallest 2.7 m; a child gymnast
/// is over 1 m.
inline constexpr double kMinStature = 0.5;
inline constexpr double kMaxStature = 2.8;
/// kg: body mass. A 1 m child weighs about 15 kg; 300 kg is beyond any athlete.
inline constexpr double kMinBodyMass = 10.0;
inline constexpr double kMaxBodyMass = 300.0;
/// The flags of a person's size (--height, --mass; flag_bounds.h).
inline constexpr NumberBound kStatureBound{kMinStature, kMaxStature, "m"};
inline constexpr NumberBound kBodyMassBound{kMinBodyMass, kMaxBodyMass, "kg"};
/// kg/m²: body mass index M/H². People range from about 12 (severe wasting) to 60; a 1.45 m,
/// 38 kg junior is 18, a 1.85 m, 85 kg senior 25. Outside [8, 80] a number was mistyped.
inline constexpr double kMinBodyMassIndex = 8.0;
inline constexpr double kMaxBodyMassIndex = 80.0;
/// m: one of Yeadon's measurements (`model yeadon`): a length, perimeter, width or depth. A
/// child's thumb is over 1 cm wide, a heavy man's hips about 1.5 m around.
inline constexpr double kMinBodyMeasurement = 1e-3;
inline constexpr double kMaxBodyMeasurement = 2.0;
/// years: an athlete's age (`model new --age`, a model's strength). Anderson's groups span
/// 18-80; children and the very old are read by the nearest group (joint_strength.h).
inline constexpr double kMinAgeYears = 5.0;
inline constexpr double kMaxAgeYears = 100.0;
inline constexpr NumberBound kAgeBound{kMinAgeYears, kMaxAgeYears, "years"};
/// N·m: a measured peak isometric joint moment. A knee extension's is 150-400 N·m, a wrist's
/// 10-40; 5000 is beyond any joint.
inline constexpr double kMinJointMomentNm = 0.1;
inline constexpr double kMaxJointMomentNm = 5000.0;

// Motion (docs/formats.md, "Motion").
/// s: the flight time T. Trampoline and diving flights last 1-3 s, a 27 m cliff dive 3 s.
inline constexpr double kMaxFlightTime = 60.0;
/// s: the shortest gap between keyframes (a 1 kHz capture). Closer keyframes make the spline's
/// second derivative, and so the inverse dynamics, blow up (a keyframe at t = 1e-9 gave NaN).
inline constexpr double kMinKeyframeGap = 1e-3;
/// s: rounding allowed below kMinKeyframeGap, so that frames exactly 1 ms apart (times i × dt,
/// rounded: 10·0.001 − 9·0.001 = 0.000999…9 s) are accepted as the capture's frame-time bound
/// promises; also below kMinKnotGap, as a stored spline's interior knots split such gaps in 50.
inline constexpr double kKeyframeGapRounding = 1e-9;
/// s: the shortest gap between interior knots of a stored spline (K = 50 sub-intervals of the
/// shortest keyframe gap), checked less kKeyframeGapRounding.
inline constexpr double kMinKnotGap = kMinKeyframeGap / 50;
/// s per frame of a capture (its "Frame Time", or `import --frame-time`): every captured flight
/// frame becomes a keyframe, so the shortest is the keyframe gap (1 kHz); the longest, 1 s,
/// is far slower than any capture (24-1000 Hz), which 100 or 3600 (minutes per frame) are not.
inline constexpr double kMinCaptureFrameTime = kMinKeyframeGap;
inline constexpr double kMaxCaptureFrameTime = 1.0;
inline constexpr NumberBound kCaptureFrameTimeBound{kMinCaptureFrameTime, kMaxCaptureFrameTime,
                                                    "s per frame"};
/// Frames of a captured flight that `import` fits (every one a keyframe of capture.motion.json):
/// 2.5 s at 1000 Hz, 21 s at 120 Hz. Fitting and picking keyframes cost about 8 ms per frame here
/// (3000 jerky frames: 24 s), so this bounds an import to about 20 s whatever the file holds.
inline constexpr int kMaxCaptureFlightFrames = 2500;
/// m: |take-off CoM|, |keyframe root position| per coordinate.
inline constexpr double kMaxPosition = 1e4;
/// m: |root translation control point| per coordinate (a 60 s fall is 18 km).
inline constexpr double kMaxTrajectoryPosition = 1e5;
/// m/s: the take-off speed. A ski jumper leaves the table at 27 m/s.
inline constexpr double kMaxTakeoffSpeed = 100.0;
/// kg·m²/s per component of the take-off angular momentum, before the finer check below. A
/// straight double somersault needs about 90.
inline constexpr double kMaxAngularMomentum = 1e5;
/// rad/s: the whole-body angular velocity the take-off angular momentum implies at the first
/// keyframe's pose, |I_G⁻¹ L|. Elite twisting reaches 25 rad/s (4 revolutions per second).
inline constexpr double kMaxBodyAngularVelocity = 200.0;
/// Keyframe tolerances: ε1 (m) and ε2 (quaternion distance, at most 2 between unit
/// quaternions).
inline constexpr double kMaxTranslationTolerance = 100.0;
inline constexpr double kMaxQuaternionTolerance = 2.0;
/// deg: |Euler angle| of a keyframe rotation (ten turns).
inline constexpr double kMaxEulerAngleDeg = 3600.0;
/// rad: the largest turn between consecutive control quaternions of a stored spline. The
/// optimiser starts from curves turning at most 1.75π (kMaxControlTurn) and its joint-turn limit
/// keeps them there; near 2π the log map that defines the turn reaches its branch point and a
/// sign-flipped control (q → −q, the same rotation) puts it there.
inline constexpr double kMaxStoredControlTurn = 1.9 * 3.14159265358979323846;

}  // namespace saltus::plausible
