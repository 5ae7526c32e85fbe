#pragma once
/// @file
/// de Leva's segment inertia parameters, both sexes: P. de Leva, "Adjustments to
/// Zatsiorsky-Seluyanov's segment inertia parameters", J. Biomech. 29(9):1223-1230, 1996,
/// Table 4. Which copies the numbers were taken from, where copies disagree and what was chosen:
/// docs/method.md, "Athletes' body models".

#include <string>
#include <vector>

namespace saltus {

enum class Sex { kFemale, kMale };

/// "female" / "male".
std::string sex_name(Sex sex);

/// The table's segments that Saltus uses (the two trunk rows are for checks and the shoulder
/// height; the other rows are composed into Saltus's 13 segments).
enum class DeLevaPart {
  kHead,         ///< VERT-MIDG (vertex to mid-gonion; the mass includes the neck)
  kTrunk,        ///< SUPR-MIDH (suprasternale to mid-hip joint centres)
  kTrunkMids,    ///< MIDS-MIDH (mid-shoulder joint centres to mid-hip), for the shoulder height
  kUpperTrunk,   ///< SUPR-XYPH (suprasternale to xiphion)
  kMiddleTrunk,  ///< XYPH-OMPH (xiphion to omphalion, the navel)
  kLowerTrunk,   ///< OMPH-MIDH
  kUpperArm,     ///< SJC-EJC
  kForearm,      ///< EJC-WJC
  kHand,         ///< WJC-MET3 (wrist joint centre to the third metacarpale)
  kThigh,        ///< HJC-KJC
  kShank,        ///< KJC-AJC (the table's alternative shank, to the ankle joint centre)
  kFoot,         ///< HEEL-TTIP
};

/// One row of Table 4 for one sex, as printed: lengths in mm for de Leva's mean subject,
/// everything else in % (of body mass, or of the segment's length).
struct DeLevaRow {
  DeLevaPart part;
  const char* name;       ///< "upper trunk"
  const char* from;       ///< landmark the CoM is measured from ("SUPR")
  const char* to;         ///< the other end ("XYPH")
  double length_mm;       ///< mean length of de Leva's subjects
  double mass_percent;    ///< % of body mass
  double com_percent;     ///< CoM position from `from`, % of length
  double r_sagittal;      ///< radius of gyration about the sagittal (antero-posterior) axis, %
  double r_transverse;    ///< about the transverse (medio-lateral) axis, %
  double r_longitudinal;  ///< about the segment's long axis, %
};

/// The rows for one sex, in DeLevaPart order.
const std::vector<DeLevaRow>& de_leva_rows(Sex sex);
const DeLevaRow& de_leva_row(Sex sex, DeLevaPart part);

/// Mean stature of de Leva's subjects, m: 1.741 (male), 1.735 (female). His lengths are for it.
double de_leva_stature(Sex sex);

}  // namespace saltus
