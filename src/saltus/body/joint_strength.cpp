#include "saltus/body/joint_strength.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "saltus/base/constants.h"
#include "saltus/base/text_format.h"
#include "saltus/body/mass_properties.h"
#include "saltus/body/strength_tables.h"

namespace saltus {

namespace {

/// Anderson et al. 2007's Table 3 normalises moments by body mass × height × g, with g = 9.81
/// (RBDL's add-on, which says it "has to be equal to the gravity parameter used by Anderson").
constexpr double kAndersonGravity = 9.81;

const AndersonRow& anderson_row(const std::string& joint, const std::string& direction,
                                const std::string& sex, const std::string& age_group) {
  for (const AndersonRow& row : anderson2007_table3())
    if (row.joint == joint && row.direction == direction && row.sex == sex &&
        row.age_group == age_group)
      return row;
  throw std::logic_error("no Anderson 2007 row for " + joint + " " + direction);
}

const GymnastRow& gymnast_row(const std::string& joint, const std::string& direction) {
  for (const GymnastRow& row : gymnast_whole_body())
    if (row.joint == joint && row.direction == direction) return row;
  throw std::logic_error("no gymnast row for " + joint + " " + direction);
}

/// Anderson's moment-velocity factor, (2c4c5 + ω(c5 − 3c4)) / (2c4c5 + ω(2c5 − 4c4)): 3/4 at
/// c4, 1/2 at c5; its zero |2c4c5 / (c5 − 3c4)| is the largest shortening speed.
double anderson_velocity_factor(const AndersonRow& r, double speed) {
  return (2 * r.c4 * r.c5 + speed * (r.c5 - 3 * r.c4)) /
         (2 * r.c4 * r.c5 + speed * (2 * r.c5 - 4 * r.c4));
}

/// The curve of one Anderson row for a person of `mass_kg` and `height_m`. The velocity factor
/// at half speed is capped at 0.45, as RBDL's fit caps it (a Hill curve bends below the chord).
StrengthCurve anderson_curve(const AndersonRow& r, double mass_kg, double height_m) {
  StrengthCurve c;
  c.source =
      "Anderson et al. 2007, " + std::string(r.sex == "male" ? "men " : "women ") + r.age_group;
  c.peak_Nm = r.c1 * mass_kg * height_m * kAndersonGravity;
  c.shape = StrengthCurve::AngleShape::kCosine;
  c.peak_angle_rad = r.c3;
  c.shape_width = r.c2;
  c.max_shortening_speed = std::abs(2 * r.c4 * r.c5 / (r.c5 - 3 * r.c4));
  c.factor_at_half_speed =
      std::clamp(anderson_velocity_factor(r, 0.5 * c.max_shortening_speed), 0.05, 0.45);
  c.eccentric_plateau = 1.1 + 0.2 * r.c6;
  return c;
}

/// The gymnast's curve of one row, scaled by `scale`; `with_angle` false where the source's
/// angle convention is not stated (shoulder horizontal ab-adduction and rotation, the forearm's
/// pronation and supination): the peak is taken at every angle.
StrengthCurve gymnast_curve(const GymnastRow& r, double scale, bool with_angle, double angle_sign,
                            const std::string& scaled_as) {
  StrengthCurve c;
  std::string direction = r.direction;
  std::replace(direction.begin(), direction.end(), '_', ' ');
  c.source = "elite gymnast's " + r.joint + " " + direction +
             (with_angle ? "" : " (at every angle)") +
             (scaled_as.empty() ? "" : ", scaled as " + scaled_as + "'s legs");
  c.peak_Nm = r.max_isometric_moment_Nm * scale;
  c.shape = with_angle ? StrengthCurve::AngleShape::kGaussian : StrengthCurve::AngleShape::kNone;
  c.angle_sign = angle_sign;
  c.peak_angle_rad = r.angle_at_peak_active_moment_rad;
  c.shape_width = r.active_angular_width_rad;
  c.max_shortening_speed = r.max_angular_velocity_rad_s;
  c.factor_at_half_speed = r.velocity_factor_at_half_max_concentric;
  c.eccentric_plateau = r.velocity_factor_at_max_eccentric;
  return c;
}

/// Where a joint coordinate's two directions come from: the table's joint and directions, and
/// how the source's angle is read.
struct Source {
  std::string kind;  ///< JointCoordinates::kind
  int coordinate;    ///< index in Cardan order
  std::string table_joint, positive, negative;
  bool anderson;  ///< hip, knee, ankle: Anderson's table for a population
  bool with_angle;
  double angle_sign;
};

const std::vector<Source>& sources() {
  static const std::vector<Source> list = {
      {"hip", 0, "hip", "flexion", "extension", true, true, 1},
      {"knee", 0, "knee", "flexion", "extension", true, true, 1},
      // Anderson's ankle "flexion" is dorsiflexion, "extension" plantar flexion.
      {"ankle", 0, "ankle", "flexion", "extension", true, true, 1},
      {"shoulder", 0, "shoulder", "flexion", "extension", false, true, 1},
      // The frontal coordinate becomes horizontal ab-adduction with the arm raised: the only
      // shoulder ab-adduction the sources give.
      {"shoulder", 1, "shoulder", "horizontal_adduction", "horizontal_abduction", false, false, 1},
      {"shoulder", 2, "shoulder", "internal_rotation", "external_rotation", false, false, 1},
      {"elbow", 0, "elbow", "flexion", "extension", false, true, 1},
      {"elbow", 2, "wrist", "pronation", "supination", false, false, 1},
      // The gymnast's lumbar angle counts trunk flexion positive; Saltus's coordinates count
      // extension positive. The thoracic joint is given the same trunk muscles.
      {"lumbar", 0, "lumbar", "extension", "flexion", false, true, -1},
      {"thoracic", 0, "lumbar", "extension", "flexion", false, true, -1},
  };
  return list;
}

/// The population's leg strength against the gymnast's, at the gymnast's size: the sum of the
/// peaks of hip and knee flexion and extension, Anderson's for the population over the gymnast's
/// (young men 0.86). The upper body and trunk scale by it.
double population_to_gymnast(const std::string& sex, const std::string& age_group) {
  double population = 0.0, gymnast = 0.0;
  for (const char* joint : {"hip", "knee"})
    for (const char* direction : {"flexion", "extension"}) {
      population += anderson_curve(anderson_row(joint, direction, sex, age_group), kGymnastMassKg,
                                   kGymnastHeightM)
                        .peak_Nm;
      gymnast += gymnast_row(joint, direction).max_isometric_moment_Nm;
    }
  return population / gymnast;
}

}  // namespace

double StrengthCurve::angle_factor(double coordinate_value) const {
  const double angle = angle_sign * coordinate_value;
  switch (shape) {
    case AngleShape::kCosine: {
      const double phase = shape_width * (angle - peak_angle_rad);
      return std::abs(phase) >= 0.5 * kPi ? 0.0 : std::cos(phase);
    }
    case AngleShape::kGaussian: {
      const double d = (angle - peak_angle_rad) / shape_width;
      return std::exp(-0.5 * d * d);
    }
    case AngleShape::kNone:
      break;
  }
  return 1.0;
}

double StrengthCurve::velocity_factor(double shortening_speed) const {
  const double v = shortening_speed / max_shortening_speed;
  if (v >= 1.0) return 0.0;
  if (v >= 0.0) {
    // Hill's hyperbola (1 − v)/(1 + v/k) through factor_at_half_speed at v = 1/2.
    const double f = factor_at_half_speed;
    const double k = 0.5 * f / (0.5 - f);
    return (1.0 - v) / (1.0 + v / k);
  }
  // Lengthening: from 1 to the plateau at v = −1, flat beyond.
  const double u = std::max(v, -1.0);
  return eccentric_plateau - (eccentric_plateau - 1.0) * (1.0 + u) * (1.0 + u);
}

double strength_capacity(const StrengthCurve& curve, double coordinate_value,
                         double shortening_speed, bool* extrapolated) {
  const double angle = curve.angle_factor(coordinate_value);
  const double velocity = curve.velocity_factor(shortening_speed);
  if (extrapolated)
    *extrapolated = angle < kMinimumAngleFactor || velocity < kMinimumVelocityFactor;
  return curve.peak_Nm * std::max(angle, kMinimumAngleFactor) *
         std::max(velocity, kMinimumVelocityFactor);
}

std::vector<StrengthRow> strength_rows(const BodyModel& model) {
  const AthleteStrength strength = athlete_strength(model);
  std::vector<StrengthRow> rows;
  for (int segment = 1; segment < model.size(); ++segment)
    for (int i = 0; i < 3; ++i) {
      const JointCoordinate& c = strength.coordinates[segment].coordinates[i];
      const CoordinateStrength& s = strength.joints[segment][i];
      if (s.positive)
        rows.push_back({model.segments[segment].joint, c.name, c.positive, *s.positive});
      if (s.negative)
        rows.push_back({model.segments[segment].joint, c.name, c.negative, *s.negative});
    }
  return rows;
}

std::string strength_reference_words(const StrengthSpec& spec) {
  std::string words =
      spec.reference == "elite-gymnast"
          ? std::string("elite gymnast (every joint the gymnast's, scaled to this body)")
          : "population: " + std::string(spec.female ? "female" : "male") + ", " +
                format_number("%g", spec.age_years) + " years (Anderson's " +
                anderson_age_group(spec.age_years) + " group)";
  if (!spec.measured.empty())
    words +=
        "; " + std::to_string(spec.measured.size()) +
        (spec.measured.size() == 1 ? " joint direction measured" : " joint directions measured");
  return words;
}

std::string anderson_age_group(double age_years) {
  if (age_years < 40.0) return "18-25";
  if (age_years <= 65.0) return "55-65";
  return "over-65";
}

AthleteStrength athlete_strength(const BodyModel& model) {
  const StrengthSpec& spec = model.strength;
  const bool gymnast = spec.reference == "elite-gymnast";
  if (!gymnast && spec.reference != "population")
    throw std::invalid_argument("unknown strength reference \"" + spec.reference +
                                "\" (population, elite-gymnast)");
  const double mass = model.total_mass();
  const double height = standing_body(model).height();
  const std::string sex = spec.female ? "female" : "male";
  const std::string age_group = anderson_age_group(spec.age_years);
  // The gymnast's moments scale with mass × height, as Anderson normalises.
  const double size_scale = mass * height / (kGymnastMassKg * kGymnastHeightM);
  const double upper_scale =
      gymnast ? size_scale : size_scale * population_to_gymnast(sex, age_group);
  const std::string population =
      "Anderson's " + std::string(spec.female ? "women " : "men ") + age_group;

  AthleteStrength out;
  out.coordinates.resize(model.size());
  out.joints.resize(model.size());
  for (int segment = 1; segment < model.size(); ++segment) {
    out.coordinates[segment] = joint_coordinates(model, segment);
    const std::string& kind = out.coordinates[segment].kind;
    for (const Source& s : sources()) {
      if (s.kind != kind) continue;
      CoordinateStrength& c = out.joints[segment][s.coordinate];
      auto curve = [&](const std::string& direction) {
        if (s.anderson && !gymnast)
          return anderson_curve(anderson_row(s.table_joint, direction, sex, age_group), mass,
                                height);
        return gymnast_curve(gymnast_row(s.table_joint, direction),
                             s.anderson ? size_scale : upper_scale, s.with_angle, s.angle_sign,
                             gymnast ? "" : population);
      };
      c.positive = curve(s.positive);
      c.negative = curve(s.negative);
    }
  }
  // What was measured replaces the peak; the curve keeps its shape.
  for (const StrengthSpec::Measured& m : spec.measured) {
    bool found = false;
    for (int segment = 1; segment < model.size(); ++segment) {
      const std::string& joint = model.segments[segment].joint;
      if (m.joint != joint && m.joint != out.coordinates[segment].kind) continue;
      for (int i = 0; i < 3; ++i) {
        const JointCoordinate& coordinate = out.coordinates[segment].coordinates[i];
        CoordinateStrength& c = out.joints[segment][i];
        const std::pair<const std::string*, std::optional<StrengthCurve>*> directions[] = {
            {&coordinate.positive, &c.positive}, {&coordinate.negative, &c.negative}};
        for (const auto& [direction, curve] : directions) {
          if (*direction != m.direction) continue;
          if (!*curve) {
            // A direction no source covers: the measured peak at every angle and speed.
            StrengthCurve flat;
            flat.source = "measured";
            flat.max_shortening_speed = std::numeric_limits<double>::infinity();
            *curve = flat;
          }
          (*curve)->peak_Nm = m.peak_moment_Nm;
          (*curve)->measured = true;
          found = true;
        }
      }
    }
    if (!found)
      throw std::invalid_argument("no joint \"" + m.joint + "\" with a direction \"" + m.direction +
                                  "\" in this model");
  }
  return out;
}

}  // namespace saltus
