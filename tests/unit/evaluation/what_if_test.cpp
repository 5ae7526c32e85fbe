// what_if (evaluation/what_if.h): the same take-off with the tuck moved or made tighter, flown
// again. Checked by independent paths: no change is the unchanged simulation bit for bit; a
// tucked back somersault opened later turns further and by about the time it gains in the tuck
// times the difference of the spin tucked and open (read off the unchanged flight); a tighter
// tuck turns further; every what-if flight keeps its take-off angular momentum (read from its
// samples' own momenta, not the integrator's state); the tuck found in the changed motion has
// moved by the shift asked for, and bends as much more as asked; the changed motion, saved and
// simulated on its own, flies the same flight.

#include "saltus/evaluation/what_if.h"

#include <gtest/gtest.h>

#include <cmath>

#include "saltus/base/constants.h"
#include "saltus/base/input_error.h"
#include "saltus/base/text_format.h"
#include "saltus/formats/motion_file.h"
#include "saltus/motion/interpolate.h"
#include "support/test_motions.h"

namespace saltus {
namespace {

MotionFile bundled(const std::string& name) {
  return load_motion_file(std::string(SALTUS_EXAMPLES_DIR) + "/motions/" + name);
}
const char* const kM1 = "M1-straight-back-somersault.motion.json";
const char* const kM2 = "M2-tucked-back-somersault.motion.json";
const char* const kM3 = "M3-tucked-double-back.motion.json";
const char* const kM7 = "M7-double-front-one-and-a-half-twists.motion.json";

/// Somersault angle φ (Yeadon's, unwrapped), radians, of each sample of a flight.
std::vector<double> somersault_angles(const SimulationResult& flight) {
  std::vector<Eigen::Quaterniond> roots;
  for (const SampleRecord& s : flight.samples)
    roots.push_back(s.segment_rotation.at(0));
  std::vector<double> out;
  for (const Eigen::Vector3d& a : unwrapped_angles(roots))
    out.push_back(a[0]);
  return out;
}

/// The mean somersault rate |dφ/dt| of a flight over [t0, t1], rad/s.
double mean_somersault_rate(const SimulationResult& flight, double t0, double t1) {
  const std::vector<double> phi = somersault_angles(flight);
  std::size_t i0 = 0, i1 = 0;
  for (std::size_t i = 0; i < flight.samples.size(); ++i) {
    if (flight.samples[i].time <= t0) i0 = i;
    if (flight.samples[i].time <= t1) i1 = i;
  }
  return std::abs(phi[i1] - phi[i0]) / (flight.samples[i1].time - flight.samples[i0].time);
}

TEST(WhatIf, NoChangeIsExactlyTheUnchangedSimulation) {
  for (const char* name : {kM2, kM7}) {
    SCOPED_TRACE(name);
    const MotionFile file = bundled(name);
    const WhatIfResult r = what_if(file.motion, file.model, WhatIfChange{});
    const SimulationResult plain = simulate_motion(file.motion, file.model);
    ASSERT_EQ(r.flight.samples.size(), plain.samples.size());
    for (std::size_t i = 0; i < plain.samples.size(); ++i) {
      EXPECT_EQ(r.flight.samples[i].com, plain.samples[i].com);
      for (std::size_t k = 0; k < plain.samples[i].segment_rotation.size(); ++k)
        EXPECT_EQ(r.flight.samples[i].segment_rotation[k].coeffs(),
                  plain.samples[i].segment_rotation[k].coeffs());
    }
    EXPECT_EQ(r.flight.landing_root_error_deg, plain.landing_root_error_deg);
    EXPECT_EQ(r.somersault_vs_unchanged_deg, 0.0);
    EXPECT_EQ(r.twist_vs_unchanged_deg, 0.0);
    EXPECT_EQ(r.change_words, "as keyframed");
    EXPECT_EQ(r.sentence.rfind("Same take-off, as keyframed: ", 0), 0u) << r.sentence;
  }
}

TEST(WhatIf, FindsTheTuckOfTuckedMotionsAndSaysAStraightOneHasNone) {
  // M2's keyframes (hip and knee flexion, degrees): 0/0 at 0 s, 20/20 at 0.3, 105/115 at 0.65,
  // 130/140 at 1.0 and 1.35, 30/30 at 1.75, 12/15 at 2.04: the bend (their mean) is 135° in the
  // hold (a little more between them, where the spline through them bulges), so "tucked" (90 %)
  // falls between 0.65 s (110°) and 1.0 s, the opening starts after 1.35 s and is done (within
  // 10 % of the fall above the landing's 13.5°) near 1.75 s.
  const MotionFile m2 = bundled(kM2);
  const TuckPhases tuck = find_tuck(interpolate_keyframes(m2.motion, m2.model), m2.model);
  ASSERT_TRUE(tuck.found) << tuck.reason;
  EXPECT_GE(tuck.peak_bend_deg, 135.0 - 1e-9);
  EXPECT_LT(tuck.peak_bend_deg, 150.0);
  EXPECT_NEAR(tuck.takeoff_bend_deg, 0.0, 1e-9);
  EXPECT_GT(tuck.tucked_s, 0.65);
  EXPECT_LT(tuck.tucked_s, 1.0);
  EXPECT_GT(tuck.open_start_s, 1.35);
  EXPECT_LT(tuck.open_start_s, 1.75);
  EXPECT_GT(tuck.opened_s, tuck.open_start_s);
  EXPECT_LT(tuck.opened_s, 1.85);
  EXPECT_TRUE(tuck.opens);
  EXPECT_LT(tuck.tuck_start_s, tuck.tucked_s);
  EXPECT_LE(tuck.tucked_s, tuck.peak_time_s);
  EXPECT_LE(tuck.peak_time_s, tuck.open_start_s);
  // The rule's levels hold where it says they do.
  const auto bend_at = [&](double t) {
    std::size_t i = 0;
    while (i + 1 < tuck.times.size() && tuck.times[i + 1] <= t)
      ++i;
    return tuck.bend_deg[i];
  };
  const double rise = tuck.peak_bend_deg - tuck.takeoff_bend_deg;
  EXPECT_NEAR(bend_at(tuck.tucked_s), 0.9 * rise, 0.02 * rise);
  EXPECT_NEAR(bend_at(tuck.tuck_start_s), 0.1 * rise, 0.02 * rise);
  // Each shift can go both ways, by no more than halves the phases it squeezes.
  EXPECT_LT(tuck.tuck_later_min_s, 0.0);
  EXPECT_GT(tuck.tuck_later_max_s, 0.0);
  EXPECT_LT(tuck.open_later_min_s, 0.0);
  EXPECT_GT(tuck.open_later_max_s, 0.0);
  EXPECT_LE(tuck.open_later_max_s, 0.5 * (2.04 - tuck.opened_s) + 1e-12);

  // M1 is straight: no tuck, said so, and a tuck change is refused with that reason.
  const MotionFile m1 = bundled(kM1);
  const WhatIf m1_what_if(m1.motion, m1.model);
  EXPECT_FALSE(m1_what_if.tuck().found);
  EXPECT_NE(m1_what_if.tuck().reason.find("no tuck"), std::string::npos)
      << m1_what_if.tuck().reason;
  WhatIfChange later;
  later.open_later_s = 0.05;
  try {
    m1_what_if.fly(later);
    ADD_FAILURE() << "M1 has no opening to move";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "--open-later");
    EXPECT_EQ(e.problem(), m1_what_if.tuck().reason);
  }
  // As it is, it still flies.
  EXPECT_NO_THROW(m1_what_if.fly(WhatIfChange{}));
}

TEST(WhatIf, EveryBundledMotionHasATuckToMoveOrSaysWhyNot) {
  std::vector<std::string> with_tuck;
  for (const char* name : {kM1, kM2, kM3, "M4-front-somersault-half-twist.motion.json",
                           "M5-front-somersault-one-and-a-half-twists.motion.json",
                           "M6-half-twist-into-one-and-a-half-front.motion.json", kM7,
                           "dive-5m-front-one-and-a-half-twists.motion.json"}) {
    SCOPED_TRACE(name);
    const MotionFile file = bundled(name);
    EvaluateOptions options;
    options.samples = 41;
    const WhatIf w(file.motion, file.model, options);
    const TuckPhases& tuck = w.tuck();
    std::printf("%s: %s\n", name,
                tuck.found ? format_number("tuck %.2f", tuck.tuck_start_s)
                                 .append(format_number("-%.2f s", tuck.tucked_s))
                                 .append(format_number(", opens %.2f", tuck.open_start_s))
                                 .append(format_number("-%.2f s", tuck.opened_s))
                                 .append(format_number(", peak bend %.0f°", tuck.peak_bend_deg))
                                 .c_str()
                           : tuck.reason.c_str());
    if (tuck.found) with_tuck.push_back(name);
    if (!tuck.found) {
      EXPECT_LT(tuck.peak_bend_deg - tuck.takeoff_bend_deg, kMinTuckBendDeg);
      EXPECT_FALSE(tuck.reason.empty());
      continue;
    }
    EXPECT_GE(tuck.peak_bend_deg - tuck.takeoff_bend_deg, kMinTuckBendDeg);
    // The extremes of the ranges, together, fly: each shift at one end, the tuck at one end of
    // its tightness.
    for (const WhatIfChange& change :
         {WhatIfChange{tuck.tuck_later_min_s, tuck.open_later_max_s, kMaxTuckScale},
          WhatIfChange{tuck.tuck_later_max_s, tuck.open_later_min_s, kMinTuckScale}}) {
      const WhatIfResult r = w.fly(change);
      EXPECT_TRUE(std::isfinite(r.landing.somersaults)) << r.change_words;
      EXPECT_LT(r.flight.landing_com_error_m, 1e-6) << r.change_words;
    }
  }
  // The straight motion, the layout twisters and the dive have no tuck; the tucked ones do.
  EXPECT_EQ(with_tuck, (std::vector<std::string>{
                           kM2, kM3, "M6-half-twist-into-one-and-a-half-front.motion.json", kM7}));
}

TEST(WhatIf, OpeningLaterInATuckedBackSomersaultTurnsFurther) {
  for (const char* name : {kM2, kM3}) {
    SCOPED_TRACE(name);
    const MotionFile file = bundled(name);
    const WhatIf w(file.motion, file.model);
    const double unchanged = std::abs(w.unchanged_landing().somersaults);
    const TuckPhases& tuck = w.tuck();
    ASSERT_TRUE(tuck.found);
    constexpr double kShift = 0.05;
    WhatIfChange later, earlier;
    later.open_later_s = kShift;
    earlier.open_later_s = -kShift;
    const WhatIfResult late = w.fly(later);
    const WhatIfResult early = w.fly(earlier);
    // A smaller moment of inertia held longer: more somersault; opened earlier, less.
    EXPECT_GT(std::abs(late.landing.somersaults), unchanged);
    EXPECT_LT(std::abs(early.landing.somersaults), unchanged);
    EXPECT_GT(late.somersault_vs_unchanged_deg, 0.0);
    EXPECT_LT(early.somersault_vs_unchanged_deg, 0.0);
    // About how much: the flight stays tucked kShift longer and is open kShift less, so it
    // gains kShift × (spin tucked − spin open), the spins read off the unchanged flight.
    const double tucked_rate =
        mean_somersault_rate(w.unchanged(), tuck.tucked_s, tuck.open_start_s);
    const double open_rate =
        mean_somersault_rate(w.unchanged(), tuck.opened_s, file.motion.flight_time());
    ASSERT_GT(tucked_rate, open_rate);
    const double expected_deg = kShift * (tucked_rate - open_rate) * kDegreesPerRadian;
    std::printf("%s: opening %.2f s later turns %.1f° further (estimate %.1f°), earlier %.1f°\n",
                name, kShift, late.somersault_vs_unchanged_deg, expected_deg,
                early.somersault_vs_unchanged_deg);
    EXPECT_NEAR(late.somersault_vs_unchanged_deg, expected_deg, 0.25 * expected_deg);
    EXPECT_NEAR(-early.somersault_vs_unchanged_deg, expected_deg, 0.25 * expected_deg);
  }
}

TEST(WhatIf, ATighterTuckTurnsFurtherALooserOneLess) {
  for (const char* name : {kM2, kM3, kM7}) {
    SCOPED_TRACE(name);
    const MotionFile file = bundled(name);
    const WhatIf w(file.motion, file.model);
    const double unchanged = std::abs(w.unchanged_landing().somersaults);
    WhatIfChange tighter, looser;
    tighter.tuck_scale = 1.1;
    looser.tuck_scale = 0.9;
    const WhatIfResult tight = w.fly(tighter);
    const WhatIfResult loose = w.fly(looser);
    std::printf(
        "%s: tuck 110 %% %+.1f°, 90 %% %+.1f° of somersault; twists %.2f, %.2f (as it "
        "is %.2f)\n",
        name, tight.somersault_vs_unchanged_deg, loose.somersault_vs_unchanged_deg,
        tight.landing.twists, loose.landing.twists, w.unchanged_landing().twists);
    EXPECT_GT(std::abs(tight.landing.somersaults), unchanged);
    EXPECT_LT(std::abs(loose.landing.somersaults), unchanged);
    // The hips and knees of these motions flex about one axis from a straight take-off: their
    // bend is scaled at every instant, so is its peak.
    EXPECT_NEAR(tight.tuck.peak_bend_deg, 1.1 * w.tuck().peak_bend_deg, 1e-6);
    EXPECT_NEAR(loose.tuck.peak_bend_deg, 0.9 * w.tuck().peak_bend_deg, 1e-6);
    // The take-off pose stays.
    const SampleRecord& a = tight.flight.samples.front();
    const SampleRecord& b = w.unchanged().samples.front();
    for (std::size_t k = 0; k < a.segment_rotation.size(); ++k)
      EXPECT_LT(a.segment_rotation[k].angularDistance(b.segment_rotation[k]), 1e-12);
  }
}

TEST(WhatIf, EveryWhatIfFlightKeepsItsTakeoffMomentum) {
  for (const char* name : {kM2, kM3, kM7}) {
    SCOPED_TRACE(name);
    const MotionFile file = bundled(name);
    const WhatIf w(file.motion, file.model);
    const TuckPhases& t = w.tuck();
    const Eigen::Vector3d takeoff = *file.motion.takeoff.angular_momentum;
    EXPECT_EQ(w.angular_momentum(), takeoff);
    for (const WhatIfChange& change : {WhatIfChange{t.tuck_later_min_s, t.open_later_max_s, 1.2},
                                       WhatIfChange{t.tuck_later_max_s, t.open_later_min_s, 0.8},
                                       WhatIfChange{0.0, 0.5 * t.open_later_max_s, 1.05}}) {
      const WhatIfResult r = w.fly(change);
      SCOPED_TRACE(r.change_words);
      double worst = 0.0;
      for (const SampleRecord& s : r.flight.samples) {
        worst = std::max(worst, (s.angular_momentum - takeoff).norm() / takeoff.norm());
        EXPECT_LT((s.com - ballistic_com(file.motion.takeoff, s.time)).norm(), 1e-6) << s.time;
      }
      EXPECT_LT(worst, 1e-6);
      EXPECT_LT(r.flight.metrics.avg_root_force, 1e-4);
    }
  }
}

TEST(WhatIf, TheTuckAndTheOpeningMoveByTheShiftAskedFor) {
  for (const char* name : {kM2, kM3, kM7}) {
    SCOPED_TRACE(name);
    const MotionFile file = bundled(name);
    const WhatIf w(file.motion, file.model);
    const TuckPhases& before = w.tuck();
    for (const auto& [tuck_later, open_later] :
         {std::pair{0.05, 0.0}, std::pair{0.0, std::min(0.08, before.open_later_max_s)},
          std::pair{-0.05, -0.06}, std::pair{before.tuck_later_min_s, before.open_later_max_s}}) {
      WhatIfChange change;
      change.tuck_later_s = tuck_later;
      change.open_later_s = open_later;
      const WhatIfResult r = w.fly(change);
      SCOPED_TRACE(r.change_words);
      ASSERT_TRUE(r.tuck.found);
      // Found again in the changed movements by the same rule: moved by the shift (to the bend
      // curve's 2.5 ms sampling).
      std::printf("%s, %s: tucked %+.4f s, opens %+.4f s\n", name, r.change_words.c_str(),
                  r.tuck.tucked_s - before.tucked_s, r.tuck.open_start_s - before.open_start_s);
      EXPECT_NEAR(r.tuck.tucked_s - before.tucked_s, tuck_later, 0.001);
      EXPECT_NEAR(r.tuck.open_start_s - before.open_start_s, open_later, 0.001);
      EXPECT_NEAR(r.tuck.tuck_start_s - before.tuck_start_s,
                  before.starts_at_takeoff ? r.tuck.tuck_start_s - before.tuck_start_s : tuck_later,
                  0.001);
      // The same bend, at other times (to the bend curve's sampling).
      EXPECT_NEAR(r.tuck.peak_bend_deg, before.peak_bend_deg, 0.01);
    }
  }
}

TEST(WhatIf, LandingWordsSayShortOrOverInTheDirectionOfTheSomersault) {
  // M2 is a back somersault (its counts are negative, forward positive): over is more turn
  // backward. Checked on magnitudes, independently of the sign convention.
  const MotionFile m2 = bundled(kM2);
  const WhatIf w(m2.motion, m2.model);
  ASSERT_LT(w.target().somersaults, 0.0);
  for (double scale : {0.85, 1.15}) {
    WhatIfChange change;
    change.tuck_scale = scale;
    const WhatIfResult r = w.fly(change);
    SCOPED_TRACE(r.sentence);
    const double over =
        360.0 * (std::abs(r.landing.somersaults) - std::abs(w.target().somersaults));
    EXPECT_NEAR(r.somersault_over_deg, over, 1e-9);
    const std::string word = r.somersault_over_deg > 0 ? " over" : " short";
    EXPECT_NE(r.verdict.find(format_number("%.0f°", std::abs(r.somersault_over_deg)) + word),
              std::string::npos);
    EXPECT_EQ(r.verdict.find("twist"), std::string::npos) << "M2 does not twist";
    EXPECT_EQ(r.within_tolerance, std::abs(r.somersault_over_deg) <= r.tolerance_deg &&
                                      std::abs(r.twist_over_deg) <= r.tolerance_deg);
    EXPECT_NE(r.sentence.find(format_number("%.2f somersaults", std::abs(r.landing.somersaults))),
              std::string::npos);
  }
  // M7 twists: the words give both, its counts as flown.
  const MotionFile m7 = bundled(kM7);
  WhatIfChange later;
  later.open_later_s = 0.05;
  const WhatIfResult r = what_if(m7.motion, m7.model, later);
  EXPECT_NE(r.sentence.find("Same take-off, opening 0.05 s later: "), std::string::npos)
      << r.sentence;
  EXPECT_NE(r.verdict.find(" in twist"), std::string::npos) << r.verdict;
  EXPECT_NE(r.sentence.find(format_number("%.2f twists", std::abs(r.landing.twists))),
            std::string::npos)
      << r.sentence;
  // As keyframed M7 lands where it was keyframed to, to the degree.
  const WhatIfResult as_it_is = what_if(m7.motion, m7.model, WhatIfChange{});
  EXPECT_LT(std::abs(as_it_is.somersault_over_deg), 0.5) << as_it_is.sentence;
  EXPECT_LT(std::abs(as_it_is.twist_over_deg), 0.5) << as_it_is.sentence;
  EXPECT_EQ(as_it_is.verdict, "you land on target");
  // A looser tuck there twists the other way (its twist is that sensitive to the tuck): said so.
  WhatIfChange looser;
  looser.tuck_scale = 0.9;
  const WhatIfResult loose = what_if(m7.motion, m7.model, looser);
  ASSERT_LT(loose.landing.twists, 0.0);
  EXPECT_NE(loose.sentence.find("twists the other way"), std::string::npos) << loose.sentence;
  EXPECT_LT(loose.twist_over_deg, -360.0);
}

TEST(WhatIf, RefusesChangesTheMotionDoesNotAllowNamingTheFlag) {
  const MotionFile file = bundled(kM2);
  const WhatIf w(file.motion, file.model);
  // "flag: problem" of the InputError, or "" when the change flies.
  const auto refused = [&](const WhatIfChange& change) {
    try {
      w.fly(change);
    } catch (const InputError& e) {
      return e.file() + ": " + e.problem();
    }
    return std::string();
  };
  WhatIfChange too_late;
  too_late.open_later_s = w.tuck().open_later_max_s + 0.01;
  EXPECT_EQ(refused(too_late).rfind("--open-later: The opening can move from", 0), 0u);
  WhatIfChange too_early;
  too_early.tuck_later_s = w.tuck().tuck_later_min_s - 0.01;
  EXPECT_EQ(refused(too_early).rfind("--tuck-later: The tuck can move from", 0), 0u);
  // Short numbers for huge ones (once 300 digits), and every digit where three decimals would
  // print the end of the range it is beyond.
  WhatIfChange huge;
  huge.open_later_s = 1e308;
  EXPECT_NE(refused(huge).find(", not +1e+308 s."), std::string::npos) << refused(huge);
  WhatIfChange just_past;
  just_past.open_later_s = w.tuck().open_later_max_s + 1e-7;
  const std::string past = refused(just_past);
  EXPECT_NE(past.find(", not +" + exact_number(just_past.open_later_s) + " s."), std::string::npos)
      << past;
  WhatIfChange at_edge;
  at_edge.open_later_s = w.tuck().open_later_max_s;
  EXPECT_EQ(refused(at_edge), "");
  WhatIfChange too_tight;
  too_tight.tuck_scale = 1.3;
  EXPECT_EQ(
      refused(too_tight).rfind("--tuck-scale: 1.3 is outside [0.8, 1.2] (the tuck's tightness", 0),
      0u)
      << refused(too_tight);
  too_tight.tuck_scale = 1.2000001;  // once "120 %: it can go from 80 to 120 %"
  EXPECT_NE(refused(too_tight).find("1.2000001 is outside"), std::string::npos)
      << refused(too_tight);
  too_tight.tuck_scale = kMaxTuckScale;
  EXPECT_EQ(refused(too_tight), "");
  WhatIfChange not_a_number;
  not_a_number.tuck_later_s = std::nan("");
  EXPECT_EQ(refused(not_a_number).rfind("--tuck-later: ", 0), 0u) << refused(not_a_number);
}

TEST(WhatIf, WorksWithoutATakeoffMomentumInTheFile) {
  // The momentum is simulate_motion's then: the constant nearest the motion's own L(t).
  const BodyModel model = test::bundled_model();
  const Motion motion = test::tuck_motion(model);
  ASSERT_FALSE(motion.takeoff.angular_momentum);
  const WhatIf w(motion, model);
  EXPECT_EQ(w.angular_momentum(), simulate_motion(motion, model).angular_momentum);
  ASSERT_TRUE(w.tuck().found);
  WhatIfChange tighter;
  tighter.tuck_scale = 1.1;
  const WhatIfResult r = w.fly(tighter);
  EXPECT_FALSE(r.flight.angular_momentum_from_file);
  EXPECT_GT(std::abs(r.landing.somersaults), std::abs(w.unchanged_landing().somersaults));
}

}  // namespace
}  // namespace saltus
