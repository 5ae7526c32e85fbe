#pragma once
/// @file
/// A motion's joint moments against what people can produce: each joint's peak moment per kg of
/// body mass beside the published maximal voluntary moment of healthy adult men at that joint, and
/// its share of it (issue 24: the optimised motion's joint loads stay "within published maximal
/// joint moments of athletes").
///
/// The rule: Saltus' joint moment is a 3-D vector whose direction the tables do not follow, so a
/// joint's bound is the largest published maximum among its directions (the knee's extension,
/// the elbow's flexion): the magnitude can reach that in that direction. Where a study gives a
/// confidence interval its lower end is taken. A joint no verified source covers has no bound and
/// is reported so, not given an invented one (docs/optimizer.md, "Joint moments against published
/// maxima").

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "saltus/body/body_model.h"
#include "saltus/evaluation/force_metrics.h"

namespace saltus {

/// One joint's published maximal voluntary moment per body mass.
struct PublishedJointMoment {
  const char* joint;         ///< the joint without its side: "knee" covers knee_l and knee_r
  double max_moment_per_kg;  ///< N·m/kg
  const char* direction;     ///< the direction the number is of ("extension")
  const char* source;        ///< authors, year, journal, volume:pages, DOI, condition
};

/// The table, in the order of docs/optimizer.md.
const std::vector<PublishedJointMoment>& published_joint_moments();

/// The entry for a model's joint ("knee_l" and "knee_r" find "knee"); nullptr where the table
/// has none.
const PublishedJointMoment* published_joint_moment(const std::string& joint);

/// One joint's peak moment per body mass and its share of the published maximum.
struct JointMomentShare {
  std::string joint;                           ///< e.g. "knee_l"
  double max_moment_per_kg = 0.0;              ///< the peak moment / body mass, N·m/kg
  std::optional<double> published_max_per_kg;  ///< none where the table has no entry
  std::optional<double> share;                 ///< max_moment_per_kg / published_max_per_kg
};

/// Every joint's share from its peak moment (N·m, in `peaks`, joint name first) and the body
/// mass (kg, > 0), in the order given.
std::vector<JointMomentShare> joint_moment_shares(
    const std::vector<std::pair<std::string, double>>& peaks, double body_mass_kg);

/// The same from a dense check's joint peaks: every joint of the model, the root left out.
std::vector<JointMomentShare> joint_moment_shares(const BodyModel& model, const DenseCheck& check);

/// The joint with the largest share among those with a published maximum; none when no joint
/// has one.
std::optional<JointMomentShare> largest_joint_moment_share(
    const std::vector<JointMomentShare>& shares);

/// The largest share in words: "largest 12 % of the published maximum (left knee, 0.35 of
/// 2.92 N·m/kg); 8 joints have no published maximum", or "no joint has a published maximum".
std::string joint_moment_share_words(const std::vector<JointMomentShare>& shares);

}  // namespace saltus
