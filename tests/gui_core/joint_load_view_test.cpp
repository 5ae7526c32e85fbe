// The Joint loads and Strength tabs (core/joint_load_view.h): the curves are the library's joint
// loads and its shares of the athlete's strength (strength_demand.h), the force's second axis is
// % of body weight, the line says the dense check's peaks in those terms with a traffic light,
// a joint the optimiser raised is marked where its raised peak is, in the words of `saltus
// optimize`, and every joint with a strength curve has a strip.

#include "core/joint_load_view.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "core/document.h"
#include "gui_core/test_motion.h"
#include "saltus/evaluation/residual_measures.h"
#include "saltus/evaluation/strength_demand.h"

namespace saltus::gui {
namespace {

class JointLoadViewTest : public ::testing::Test {
 protected:
  void SetUp() override { document_.load(test::gui_test_motion_path(), "", 41); }
  const BodyModel& model() const { return document_.file().model; }
  const MotionEvaluation& before() const { return document_.evaluation(Stage::kBefore); }
  Document document_;
};

TEST_F(JointLoadViewTest, CurvesAreTheJointsLoadsAndItsShareOfTheAthletesStrength) {
  const int knee = model().joint_index("knee_l");
  const JointLoadView view =
      joint_load_view(model(), knee, before().samples, before().check, nullptr, nullptr);
  ASSERT_EQ(view.force.lines.size(), 1u);
  ASSERT_EQ(view.moment.lines.size(), 2u);  // |M| and its share of strength
  for (std::size_t k = 0; k < before().samples.size(); ++k) {
    const SampleRecord& r = before().samples[k];
    EXPECT_DOUBLE_EQ(view.force.lines[0].y[k], r.joint_wrench[knee].head<3>().norm());
    EXPECT_DOUBLE_EQ(view.moment.lines[0].y[k], r.joint_wrench[knee].tail<3>().norm());
    EXPECT_DOUBLE_EQ(view.moment.lines[1].y[k], 100.0 * r.strength_share[knee]);
  }
  EXPECT_TRUE(view.moment.lines[1].right_axis);
  // Named as people name it.
  EXPECT_NE(view.moment.title.find("left knee"), std::string::npos) << view.moment.title;
  EXPECT_EQ(view.moment.title.find("knee_l"), std::string::npos) << view.moment.title;
  // % of body weight: 100 % at m·g.
  EXPECT_DOUBLE_EQ(view.force.y2_per_y * body_weight_N(model()), 100.0);
  // The largest share is the dense check's, with its traffic light and its direction's words.
  const JointStrengthPeak& peak = before().check.strength_peaks[knee];
  ASSERT_GE(peak.coordinate, 0);
  ASSERT_TRUE(view.share);
  EXPECT_EQ(*view.share, peak.share);
  EXPECT_EQ(view.light, strength_light(view.share));
  EXPECT_NE(view.summary.find(strength_direction_words(model(), knee, peak)), std::string::npos)
      << view.summary;
  const JointLoadPeak& load = before().check.joint_peaks[knee];
  char force[64];
  std::snprintf(force, sizeof force, "Peak force %.3g N (%.0f %% of body weight)", load.force_N,
                100.0 * load.force_N / body_weight_N(model()));
  EXPECT_EQ(view.summary.rfind(force, 0), 0u) << view.summary;
  EXPECT_TRUE(view.raised.empty());
  EXPECT_THROW(joint_load_view(model(), 99, before().samples, before().check, nullptr, nullptr),
               std::out_of_range);
}

TEST_F(JointLoadViewTest, EveryJointWithAStrengthCurveHasAStrip) {
  const std::vector<StrengthStrip> strips =
      strength_strips(model(), before().samples, before().check);
  int covered = 0;
  for (int k = 1; k < model().size(); ++k)
    covered += before().check.strength_peaks[k].coordinate >= 0;
  ASSERT_EQ(static_cast<int>(strips.size()), covered);
  ASSERT_FALSE(strips.empty());
  for (const StrengthStrip& strip : strips) {
    SCOPED_TRACE(strip.joint);
    ASSERT_EQ(strip.shares.size(), before().samples.size());
    for (std::size_t i = 0; i < strip.shares.size(); ++i)
      EXPECT_EQ(strip.shares[i], before().samples[i].strength_share[strip.segment]);
    EXPECT_EQ(strip.peak, before().check.strength_peaks[strip.segment].share);
    // The dense check's peak is at least every sampled share (it looks between the samples).
    EXPECT_GE(strip.peak + 1e-9, *std::max_element(strip.shares.begin(), strip.shares.end()));
    EXPECT_EQ(strip.peak_words.rfind(
                  strength_direction_words(model(), strip.segment,
                                           before().check.strength_peaks[strip.segment]),
                  0),
              0u)
        << strip.peak_words;
  }
  // A joint beyond the athlete's strength says why in the words of `saltus evaluate`.
  DenseCheck over = before().check;
  const int knee = model().joint_index("knee_l");
  over.strength_peaks[knee].share = 1.3;
  for (const StrengthStrip& strip : strength_strips(model(), before().samples, over))
    if (strip.segment == knee) {
      const std::vector<std::string> lines = over_strength_lines(model(), over.strength_peaks);
      ASSERT_EQ(lines.size(), 1u);
      EXPECT_EQ(strip.peak_words, lines.front());
    }
}

TEST_F(JointLoadViewTest, AJointTheOptimiserRaisedIsMarkedWhereItsPeakIs) {
  const int hip = model().joint_index("hip_l");
  DenseCheck raised = before().check;
  raised.joint_peaks[hip].moment_Nm *= 4.71;
  raised.joint_peaks[hip].moment_time_s = 0.42;
  const JointLoadView view =
      joint_load_view(model(), hip, before().samples, before().check, &before().samples, &raised);
  ASSERT_EQ(view.moment.lines.size(), 4u);  // before and after, each with its share of strength
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

TEST(StrengthLight, GreenAmberRedByTheShareOfTheAthletesStrength) {
  EXPECT_EQ(strength_light(std::nullopt), StrengthLight::kUnknown);
  EXPECT_EQ(strength_light(0.3), StrengthLight::kGreen);
  EXPECT_EQ(strength_light(kAmberShare), StrengthLight::kAmber);
  EXPECT_EQ(strength_light(1.0), StrengthLight::kAmber);
  EXPECT_EQ(strength_light(1.01), StrengthLight::kRed);
  EXPECT_EQ(strength_light_words(StrengthLight::kRed), "beyond the athlete's strength");
  // Red above 100 %, amber near it, green paler towards 0.
  const Rgb red = strength_light_colour(StrengthLight::kRed);
  EXPECT_EQ(strength_share_colour(1.3).r, red.r);
  EXPECT_GT(strength_share_colour(0.05).g, strength_share_colour(0.7).g);
}

}  // namespace
}  // namespace saltus::gui
