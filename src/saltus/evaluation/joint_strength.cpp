#include "saltus/evaluation/joint_strength.h"

#include <algorithm>

#include "saltus/base/text_format.h"
#include "saltus/body/segment_names.h"

namespace saltus {

namespace {

/// A share in per cent: "12 %", "3.4 %".
std::string percent_words(double share) {
  const double percent = 100.0 * share;
  return format_number(percent >= 10.0 ? "%.0f %%" : "%.1f %%", percent);
}

}  // namespace

const std::vector<PublishedJointMoment>& published_joint_moments() {
  // Only numbers read in the sources themselves. Hips, ankles, shoulders and the trunk (lumbar,
  // thoracic) have no entry: no source giving their maximal moment per kg could be verified,
  // and a joint without one is reported as such rather than given a guessed bound (searched
  // again 2026-11-27; docs/optimizer.md lists what was read and why none of it was taken).
  static const std::vector<PublishedJointMoment> kTable = {
      /// Šarabon N, Kozinc Ž, Perman M (2021). Establishing reference values for isometric knee
      /// extension and flexion strength. Front. Physiol. 12:767941, doi:10.3389/fphys.2021.767941.
      /// Meta-analysis of 411 studies, body-mass-normalised isometric moments: adult healthy
      /// males, mid-range knee angle, pooled 95 % CI 2.92-3.45 N·m/kg for extension (flexion
      /// 1.15-1.62 N·m/kg). Taken: extension, the lower end, 2.92 N·m/kg.
      {"knee", 2.92, "extension",
       "Šarabon, Kozinc & Perman 2021, Front. Physiol. 12:767941 (doi:10.3389/fphys.2021.767941): "
       "isometric knee extension, adult healthy males, mid-range knee angle, pooled 95 % CI "
       "2.92-3.45 N·m/kg (lower end taken); flexion 1.15-1.62 N·m/kg"},
      /// Lategan L, Krüger PE (2003). Normative isokinetic peak torque values for elbow flexion
      /// and extension in young South African men. Afr. J. Phys. Health Educ. Recreat. Dance,
      /// 2003 Special Edition: 165-172. 199 healthy young men, Cybex 340, concentric isokinetic
      /// peak torque of the non-dominant elbow: flexion 78 % of body mass (± 12.4), extension 67 %
      /// (± 12.5), "% of body mass" being N·m per kg × 100. Taken: flexion, 0.78 N·m/kg.
      {"elbow", 0.78, "flexion",
       "Lategan & Krüger 2003, Afr. J. Phys. Health Educ. Recreat. Dance, Special Edition "
       "165-172: concentric isokinetic elbow flexion peak torque, 199 young men, 78 % of body "
       "mass (0.78 N·m/kg; extension 0.67)"},
  };
  return kTable;
}

const PublishedJointMoment* published_joint_moment(const std::string& joint) {
  const std::string base = split_side(joint).second;  // "knee_l" -> "knee"
  for (const PublishedJointMoment& entry : published_joint_moments())
    if (base == entry.joint) return &entry;
  return nullptr;
}

std::vector<JointMomentShare> joint_moment_shares(
    const std::vector<std::pair<std::string, double>>& peaks, double body_mass_kg) {
  std::vector<JointMomentShare> shares;
  if (!(body_mass_kg > 0.0)) return shares;
  for (const auto& [joint, peak_Nm] : peaks) {
    JointMomentShare s;
    s.joint = joint;
    s.max_moment_per_kg = peak_Nm / body_mass_kg;
    if (const PublishedJointMoment* entry = published_joint_moment(joint)) {
      s.published_max_per_kg = entry->max_moment_per_kg;
      s.share = s.max_moment_per_kg / entry->max_moment_per_kg;
    }
    shares.push_back(std::move(s));
  }
  return shares;
}

std::vector<JointMomentShare> joint_moment_shares(const BodyModel& model, const DenseCheck& check) {
  std::vector<std::pair<std::string, double>> peaks;
  const int n = std::min(model.size(), static_cast<int>(check.joint_peaks.size()));
  for (int k = 1; k < n; ++k)
    peaks.emplace_back(model.segments[k].joint, check.joint_peaks[k].moment_Nm);
  return joint_moment_shares(peaks, model.total_mass());
}

std::optional<JointMomentShare> largest_joint_moment_share(
    const std::vector<JointMomentShare>& shares) {
  std::optional<JointMomentShare> largest;
  for (const JointMomentShare& s : shares)
    if (s.share && (!largest || *s.share > *largest->share)) largest = s;
  return largest;
}

std::string joint_moment_share_words(const std::vector<JointMomentShare>& shares) {
  const std::optional<JointMomentShare> largest = largest_joint_moment_share(shares);
  if (!largest) return "no joint has a published maximum";
  const auto without = std::count_if(shares.begin(), shares.end(),
                                     [](const JointMomentShare& s) { return !s.share; });
  std::string words = "largest " + percent_words(*largest->share) + " of the published maximum (" +
                      joint_label(largest->joint) +
                      format_number(", %.3g", largest->max_moment_per_kg) +
                      format_number(" of %.2f N·m/kg)", *largest->published_max_per_kg);
  if (without == 1) words += "; 1 joint has no published maximum";
  if (without > 1) words += "; " + std::to_string(without) + " joints have no published maximum";
  return words;
}

}  // namespace saltus
