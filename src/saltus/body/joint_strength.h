#pragma once
/// @file
/// What an athlete's joints can produce: for each joint coordinate (joint_coordinates.h) and
/// each of its two directions, the maximal voluntary moment as a function of the coordinate's
/// angle and its shortening speed, from the published tables (strength_tables.h) scaled to the
/// athlete by the rule of their StrengthSpec (docs/method.md, "Strength").
///
/// A curve is peak · angle factor · velocity factor. The angle factor is the source's: Anderson
/// et al. 2007's cos(c2·(θ − c3)), the gymnast's Gaussian exp(−(θ − θ*)²/2σ²); outside the
/// angles the studies measured these fall towards zero as extrapolations, so it is held at no
/// less than kMinimumAngleFactor there, and a capacity that used that floor says so. The velocity
/// factor is a Hill curve through 1 at rest, the source's factor at half the largest shortening
/// speed and 0 at it, rising to the source's eccentric plateau when the muscle lengthens (the
/// form RBDL's add-on fits to both sources). Passive tissue moments are left out.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "saltus/body/body_model.h"
#include "saltus/body/joint_coordinates.h"

namespace saltus {

/// The angle factor's floor, where a curve is extrapolated past the measured range (a stated
/// assumption, not a measurement: docs/method.md, "Strength").
inline constexpr double kMinimumAngleFactor = 0.25;
/// The velocity factor's floor past the largest shortening speed (the moment a muscle holds
/// there is near zero, but a share of infinity says nothing a coach can use).
inline constexpr double kMinimumVelocityFactor = 0.05;

/// One direction's curve.
struct StrengthCurve {
  enum class AngleShape { kCosine, kGaussian, kNone };
  std::string source;     ///< "Anderson et al. 2007, men 18-25" or "elite gymnast (Jackson 2010)"
  double peak_Nm = 0.0;   ///< the isometric peak for this athlete, N·m
  bool measured = false;  ///< the peak is the athlete's own (StrengthSpec::measured)
  AngleShape shape = AngleShape::kNone;
  /// The source's angle = angle_sign · coordinate value (the gymnast's lumbar counts flexion +).
  double angle_sign = 1.0;
  double peak_angle_rad = 0.0;         ///< c3, or θ*
  double shape_width = 1.0;            ///< c2 (1/rad) for the cosine, σ (rad) for the Gaussian
  double max_shortening_speed = 1.0;   ///< rad/s, where the velocity factor reaches 0
  double factor_at_half_speed = 0.25;  ///< at half of it
  double eccentric_plateau = 1.1;      ///< when lengthening at that speed or faster

  /// The angle factor at the coordinate value (rad), before the floor.
  double angle_factor(double coordinate_value) const;
  /// The velocity factor at a shortening speed (rad/s; negative: lengthening), before the floor.
  double velocity_factor(double shortening_speed) const;
};

/// The capacity of one curve at a coordinate value (rad) and shortening speed (rad/s), N·m,
/// with the floors applied; `extrapolated`, when given, says whether a floor was used.
double strength_capacity(const StrengthCurve& curve, double coordinate_value,
                         double shortening_speed, bool* extrapolated = nullptr);

/// A coordinate's two directions; none where no source covers the direction.
struct CoordinateStrength {
  std::optional<StrengthCurve> positive;  ///< towards JointCoordinate::positive
  std::optional<StrengthCurve> negative;
};

/// Every non-root joint's coordinates (joint_coordinates) and their strength, segment order
/// (index 0, the root, empty).
struct AthleteStrength {
  std::vector<JointCoordinates> coordinates;
  std::vector<std::array<CoordinateStrength, 3>> joints;
};

/// The athlete's strength from model.strength, its total mass and its standing height. Throws
/// std::invalid_argument for a spec the tables cannot serve (an unknown reference, or a measured
/// joint or direction the model has not).
AthleteStrength athlete_strength(const BodyModel& model);

/// One joint direction's strength as `model info` lists it.
struct StrengthRow {
  std::string joint;       ///< "hip_l"
  std::string coordinate;  ///< "hip_flexion_l"
  std::string direction;   ///< "flexion"
  StrengthCurve curve;
};
/// Every covered direction of the athlete, model order, positive direction first.
std::vector<StrengthRow> strength_rows(const BodyModel& model);

/// Whose strength a spec gives, for people: "population: male, 21 years (Anderson's 18-25
/// group)", "elite-gymnast", with "; 2 joint directions measured" when some were.
std::string strength_reference_words(const StrengthSpec& spec);

/// Anderson's age group for an age in years: under 40 "18-25", 40 to 65 "55-65", over 65
/// "over-65" (the nearest group the table has; children are read as young adults).
std::string anderson_age_group(double age_years);

}  // namespace saltus
