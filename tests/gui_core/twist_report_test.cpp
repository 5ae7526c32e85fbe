// The Twist panel's table and chart (core/twist_report.h): rows carry the library's numbers and
// add up to the total, labels say what each row and curve is, and a flight
// without tilt gets the library's sentence alone (no table, no percentages of nothing).

#include "core/twist_report.h"

#include <gtest/gtest.h>

#include <cmath>

#include "saltus/formats/motion_file.h"

namespace saltus::gui {
namespace {

std::string motion_path(const std::string& name) {
  return std::string(SALTUS_EXAMPLES_DIR) + "/motions/" + name;
}

/// A result as twist_sources makes one, with round numbers: 24° of tilt, 17° from the right arm,
/// 6° from the take-off, −1° from the left arm (against), 2° from the legs, 0° from the trunk
/// (the shares add up to the total, as Shapley values do).
TwistSources made_up() {
  TwistSources s;
  s.reference_time_s = 0.6;
  s.total_tilt_deg = 24.0;
  s.twists = 1.5;
  s.shares = {{"take-off", 6.0, 25.0},
              {"left arm", -1.0, -100.0 / 24.0},
              {"right arm", 17.0, 1700.0 / 24.0},
              {"legs", 2.0, 200.0 / 24.0},
              {"trunk", 0.0, 0.0}};
  s.interaction_deg = 0.0;
  s.times = {0.0, 0.6, 1.2};
  s.flight_names = {"actual",       "take-off only", "without left arm", "without right arm",
                    "without legs", "without trunk"};
  s.tilt_deg = {{0, 24, 30}, {0, 6, 7}, {0, 25, 31}, {0, 7, 8}, {0, 22.5, 28}, {0, 24, 30}};
  s.sentence =
      "Of the 24° of tilt at mid-flight, 71 % came from the right arm, 25 % from the "
      "take-off, 8 % from the legs.";
  return s;
}

TEST(TwistReport, RowsAreTheSourcesThenTheTotal) {
  const TwistSources s = made_up();
  const TwistReport r = twist_report(s);
  ASSERT_TRUE(r.tilted);
  EXPECT_EQ(r.sentence, s.sentence);
  ASSERT_EQ(r.rows.size(), s.shares.size() + 1);
  const std::vector<std::string> labels = {"Take-off", "Left arm", "Right arm", "Legs", "Trunk"};
  for (std::size_t i = 0; i < s.shares.size(); ++i) {
    EXPECT_EQ(r.rows[i].kind, TwistRow::Kind::kSource);
    EXPECT_EQ(r.rows[i].label, labels[i]);
    EXPECT_EQ(r.rows[i].tilt_deg, s.shares[i].tilt_deg);
    EXPECT_EQ(r.rows[i].percent, s.shares[i].percent);
  }
  const TwistRow& total = r.rows.back();
  EXPECT_EQ(total.kind, TwistRow::Kind::kTotal);
  EXPECT_EQ(total.label, "Total");
  EXPECT_EQ(total.tilt_deg, s.total_tilt_deg);
  EXPECT_EQ(total.percent_text, "100 %");
}

TEST(TwistReport, SourceRowsAddUpToTheTotal) {
  const TwistReport r = twist_report(made_up());
  double tilt = 0.0, percent = 0.0;
  for (const TwistRow& row : r.rows)
    if (row.kind == TwistRow::Kind::kSource) {
      tilt += row.tilt_deg;
      percent += row.percent;
    }
  EXPECT_NEAR(tilt, r.rows.back().tilt_deg, 1e-12);
  EXPECT_NEAR(percent, 100.0, 1e-9);
  EXPECT_EQ(r.rows[3].tilt_text, "2.0°");
  EXPECT_EQ(r.rows[3].percent_text, "8 %");
}

TEST(TwistReport, NumbersAreWrittenForPeople) {
  const TwistReport r = twist_report(made_up());
  EXPECT_EQ(r.rows[0].tilt_text, "6.0°");
  EXPECT_EQ(r.rows[0].percent_text, "25 %");
  EXPECT_EQ(r.rows[1].tilt_text, "\u22121.0°");  // a real minus: against the total
  EXPECT_EQ(r.rows[1].percent_text, "\u22124 %");
  EXPECT_EQ(r.rows[2].percent_text, "71 %");
  EXPECT_EQ(r.rows[4].tilt_text, "0.0°");
  EXPECT_EQ(tilt_text(-0.04), "0.0°");  // no "−0.0°"
  EXPECT_EQ(percent_text(-0.4), "0 %");
  EXPECT_EQ(r.summary,
            "Tilt 24.0° at mid-flight (t = 0.60 s; θ = 24.0° in the chart); 1.50 twists to the "
            "left.");
}

TEST(TwistReport, TiltIsCountedInTheDirectionOfTheTotal) {
  // The same flight mirrored: θ < 0 and twisting to the right. The table reads as before.
  TwistSources s = made_up();
  s.total_tilt_deg = -s.total_tilt_deg;
  s.twists = -s.twists;
  for (TwistShare& share : s.shares)
    share.tilt_deg = -share.tilt_deg;  // percents keep their sign: of the total
  const TwistReport mirrored = twist_report(s), original = twist_report(made_up());
  ASSERT_EQ(mirrored.rows.size(), original.rows.size());
  for (std::size_t i = 0; i < mirrored.rows.size(); ++i) {
    EXPECT_EQ(mirrored.rows[i].tilt_text, original.rows[i].tilt_text) << i;
    EXPECT_EQ(mirrored.rows[i].percent_text, original.rows[i].percent_text) << i;
  }
  EXPECT_EQ(mirrored.rows[1].tilt_text, "\u22121.0°");  // the left arm still works against it
  EXPECT_EQ(mirrored.summary,
            "Tilt 24.0° at mid-flight (t = 0.60 s; θ = \u221224.0° in the chart); 1.50 twists to "
            "the right.");
  // The chart keeps the library's signed θ.
  EXPECT_EQ(mirrored.chart.lines[0].y, s.tilt_deg[0]);
}

TEST(TwistReport, TheChartHasEveryFlightLabelledAndMidFlightMarked) {
  const TwistSources s = made_up();
  const ChartSpec c = twist_report(s).chart;
  EXPECT_EQ(c.x_title, "time (s)");
  EXPECT_EQ(c.y_title, "tilt θ (°)");
  ASSERT_EQ(c.lines.size(), s.flight_names.size());
  // The actual flight first (a band under the others), "take-off only" last (over them).
  const std::vector<std::string> labels = {
      "actual flight",       "left arm made symmetric", "right arm made symmetric",
      "legs made symmetric", "trunk made symmetric",    "take-off only"};
  const std::vector<std::size_t> flights = {0, 2, 3, 4, 5, 1};
  for (std::size_t k = 0; k < c.lines.size(); ++k) {
    EXPECT_EQ(c.lines[k].label, labels[k]);
    EXPECT_EQ(c.lines[k].x, s.times);
    EXPECT_EQ(c.lines[k].y, s.tilt_deg[flights[k]]) << labels[k];
  }
  EXPECT_GT(c.lines[0].width, c.lines[1].width);
  EXPECT_TRUE(c.lines.back().dashed);
  ASSERT_EQ(c.markers.size(), 1u);
  EXPECT_EQ(c.markers[0].x, s.reference_time_s);
  EXPECT_NE(c.markers[0].label.find("mid-flight"), std::string::npos);
}

TEST(TwistReport, AFlightNamedOtherwiseKeepsTheLibrarysName) {
  TwistSources s = made_up();
  s.flight_names[3] = "without something new";
  EXPECT_EQ(twist_chart(s).lines[2].label, "without something new");
}

TEST(TwistReport, NoTiltGivesTheSentenceAloneWithoutATableOfZeros) {
  TwistSources s = made_up();
  s.total_tilt_deg = 0.004;
  for (TwistShare& share : s.shares)
    share.tilt_deg = share.percent = 0.0;
  s.interaction_deg = 0.004;
  s.twists = 0.0;
  s.sentence = "The body is tilted by 0.0° at mid-flight: nothing to twist with.";
  const TwistReport r = twist_report(s);
  EXPECT_FALSE(r.tilted);
  EXPECT_TRUE(r.rows.empty());
  EXPECT_EQ(r.sentence, s.sentence);
  EXPECT_EQ(r.summary, "Tilt 0.0° at mid-flight (t = 0.60 s); 0.00 twists.");
}

TEST(TwistReport, TheStraightBackSomersaultHasNothingToShare) {
  const MotionFile f = load_motion_file(motion_path("M1-straight-back-somersault.motion.json"));
  const TwistReport r = twist_report(twist_sources(f.motion, f.model));
  EXPECT_FALSE(r.tilted);
  EXPECT_TRUE(r.rows.empty());
  EXPECT_NE(r.sentence.find("nothing to twist with"), std::string::npos) << r.sentence;
}

}  // namespace
}  // namespace saltus::gui
