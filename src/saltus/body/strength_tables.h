#pragma once
/// @file
/// The published strength tables Saltus judges joint moments by, as read from
/// resources/strength/ (compiled into the library; provenance in that folder's README.md):
/// Anderson, Madigan & Nussbaum 2007's Table 3 (hip, knee and ankle by sex and age group) and the
/// whole-body set of one elite male gymnast compiled in RBDL's muscle add-on (Millard et al.).
/// Readers only: how the curves are built from these numbers is joint_strength.h.

#include <string>
#include <vector>

namespace saltus {

/// The embedded CSV files (src/saltus/embed_text.cmake), joined by embedded_text().
extern const char* const kAnderson2007Table3Csv[];
extern const char* const kGymnastWholeBodyCsv[];

/// One row of Anderson et al. 2007, Table 3 (the mean): the active moment-angle and
/// moment-velocity coefficients c1..c6 and the passive moment-angle ones b1, k1, b2, k2, moments
/// normalised by body mass × height × g.
struct AndersonRow {
  std::string joint;      ///< "hip", "knee", "ankle"
  std::string direction;  ///< "extension", "flexion" (ankle: plantar flexion, dorsiflexion)
  std::string sex;        ///< "male", "female"
  std::string age_group;  ///< "18-25", "55-65", "over-65"
  double c1, c2, c3, c4, c5, c6, b1, k1, b2, k2;
};
/// The 36 mean rows, in the file's order.
const std::vector<AndersonRow>& anderson2007_table3();

/// One row of the gymnast's whole-body set, in N·m, rad and rad/s at his own size.
struct GymnastRow {
  std::string joint;      ///< "hip", "knee", "ankle", "shoulder", "elbow", "wrist", "lumbar"
  std::string direction;  ///< "extension", "horizontal_adduction", "internal_rotation", ...
  double max_isometric_moment_Nm;
  double max_angular_velocity_rad_s;  ///< the largest shortening speed
  double angle_at_peak_active_moment_rad;
  double active_angular_width_rad;
  double velocity_factor_at_max_eccentric;
  double velocity_factor_at_half_max_concentric;
  double angle_at_zero_passive_moment_rad;
  double angle_at_unit_passive_moment_rad;
};
/// The 22 rows, in the file's order.
const std::vector<GymnastRow>& gymnast_whole_body();

/// The gymnast whose strength the whole-body set is (21 years, male).
inline constexpr double kGymnastMassKg = 69.6;
inline constexpr double kGymnastHeightM = 1.732;

}  // namespace saltus
