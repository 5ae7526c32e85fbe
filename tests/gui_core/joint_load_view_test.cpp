// The Joint loads tab (core/joint_load_view.h): the curves are the library's joint loads, the
// second axes are % of body weight and % of the published maximum for this athlete, the line
// says the dense check's peaks in those terms with a traffic light, and a joint the optimiser
// raised is marked where its raised peak is, in the words of `saltus optimize`.

#include "core/joint_load_view.h"

#include <gtest/gtest.h>

#include <cstdio>

#include "core/document.h"
#include "gui_core/test_motion.h"
#include "saltus/evaluation/joint_strength.h"
#include "saltus/evaluation/residual_measures.h"

namespace saltus::gui {
namespace {

class JointLoadViewTest : public ::testing::Test {
 protected:
  void SetUp() override { document_.load(test::gui_test_motion_path(), "", 41); }
  const BodyModel& model() const { return document_.file().model; }
  const MotionEvaluation& before() const { return document_.evaluation(Stage::kBefore); }
  Document document_;
};

TEST_F(JointLoadViewTest, CurvesAreTheJointsLoadsWithBodyWeightAndStrengthAxes) {
  const int knee = model().joint_index("knee_l");
  const JointLoadView view =
      joint_load_view(model(), knee, before().samples, before().check, nullptr, nullptr);
  ASSERT_EQ(view.force.lines.size(), 1u);
  ASSERT_EQ(view.moment.lines.size(), 1u);
  for (std::size_t k = 0; k < before().samples.size(); ++k) {
    EXPECT_DOUBLE_EQ(view.force.lines[0].y[k],
                     before().samples[k].joint_wrench[knee].head<3>().norm());
    EXPECT_DOUBLE_EQ(view.moment.lines[0].y[k],
                     before().samples[k].joint_wrench[knee].tail<3>().norm());
  }
  // Named as people name it.
  EXPECT_NE(view.moment.title.find("left knee"), std::string::npos) << view.moment.title;
  EXPECT_EQ(view.moment.title.find("knee_l"), std::string::npos) << view.moment.title;
  // % of body weight: 100 % at m·g.
  EXPECT_DOUBLE_EQ(view.force.y2_per_y * body_weight_N(model()), 100.0);
  // % of the published maximum: the knee's per kg times this athlete's mass is 100 %.
  const PublishedJointMoment* knee_max = published_joint_moment("knee_l");
  ASSERT_NE(knee_max, nullptr);
  EXPECT_NEAR(view.moment.y2_per_y * knee_max->max_moment_per_kg * model().total_mass(), 100.0,
              1e-9);
  // The share is the library's (joint_moment_shares), with its traffic light.
  for (const JointMomentShare& share : joint_moment_shares(model(), before().check))
    if (share.joint == "knee_l") {
      ASSERT_TRUE(view.share && share.share);
      EXPECT_NEAR(*view.share, *share.share, 1e-12);
    }
  EXPECT_EQ(view.light, strength_light(view.share));
  const JointLoadPeak& peak = before().check.joint_peaks[knee];
  char force[64];
  std::snprintf(force, sizeof force, "Peak force %.3g N (%.0f %% of body weight)", peak.force_N,
                100.0 * peak.force_N / body_weight_N(model()));
  EXPECT_EQ(view.summary.rfind(force, 0), 0u) << view.summary;
  EXPECT_NE(view.summary.find("of the published maximum for this athlete"), std::string::npos);
  EXPECT_TRUE(view.raised.empty());
  // A joint without a published maximum says so and has no second moment axis.
  const int neck = model().joint_index("thoracic");
  if (neck >= 0 && !published_joint_moment("thoracic")) {
    const JointLoadView no_max =
        joint_load_view(model(), neck, before().samples, before().check, nullptr, nullptr);
    EXPECT_FALSE(no_max.share);
    EXPECT_EQ(no_max.moment.y2_per_y, 0.0);
    EXPECT_EQ(no_max.light, StrengthLight::kUnknown);
  }
  EXPECT_THROW(joint_load_view(model(), 99, before().samples, before().check, nullptr, nullptr),
               std::out_of_range);
}

TEST_F(JointLoadViewTest, AJointTheOptimiserRaisedIsMarkedWhereItsPeakIs) {
  const int hip = model().joint_index("hip_l");
  DenseCheck raised = before().check;
  raised.joint_peaks[hip].moment_Nm *= 4.71;
  raised.joint_peaks[hip].moment_time_s = 0.42;
  const JointLoadView view =
      joint_load_view(model(), hip, before().samples, before().check, &before().samples, &raised);
  ASSERT_EQ(view.moment.lines.size(), 2u);  // before and after
  EXPECT_TRUE(view.raised_past_limit);
  EXPECT_EQ(view.summary.rfind("After optimisation: peak force", 0), 0u) << view.summary;
  ASSERT_EQ(view.moment.markers.size(), 1u);
  EXPECT_DOUBLE_EQ(view.moment.markers[0].x, 0.42);
  EXPECT_EQ(view.moment.markers[0].label, "raised 4.71x by the optimiser");
  EXPECT_TRUE(view.force.markers.empty());
  // The words of `saltus optimize`.
  const JointLoadRise rise = largest_joint_load_rise(model(), before().check, raised);
  EXPECT_EQ(view.raised,
            "Raised by the optimiser: " + joint_load_rise_words(rise, body_weight_N(model())) +
                "; " + joint_load_verdict_words(rise));
  EXPECT_EQ(joint_choice_label(model(), hip, &rise),
            "Left hip (left thigh) — 4.71x its peak before");
  // A rise within kMarkedJointRise is not marked.
  raised.joint_peaks[hip].moment_Nm = before().check.joint_peaks[hip].moment_Nm * 1.05;
  const JointLoadView small =
      joint_load_view(model(), hip, before().samples, before().check, &before().samples, &raised);
  EXPECT_TRUE(small.raised.empty());
  EXPECT_TRUE(small.moment.markers.empty());
}

TEST(StrengthLight, GreenAmberRedByTheShareOfTheMaximum) {
  EXPECT_EQ(strength_light(std::nullopt), StrengthLight::kUnknown);
  EXPECT_EQ(strength_light(0.3), StrengthLight::kGreen);
  EXPECT_EQ(strength_light(kAmberShare), StrengthLight::kAmber);
  EXPECT_EQ(strength_light(1.0), StrengthLight::kAmber);
  EXPECT_EQ(strength_light(1.01), StrengthLight::kRed);
  EXPECT_EQ(strength_light_words(StrengthLight::kRed), "beyond its maximum");
}

}  // namespace
}  // namespace saltus::gui
