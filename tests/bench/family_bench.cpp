// The family sweeps (docs/performance.md): default `optimize_motion` on physically exact flights
// (studies/exact_flights.h: the mixed family, the twisting one and the hard twisting one), on
// every bundled motion, and on every bundled motion flown by each athlete of a seeded family
// (support/athlete_family.h, issue 25; docs/studies.md). Run by name, one run each ('Family' alone
// matches all four):
//   build/release/tests/saltus_benchmarks --benchmark_filter='ExactFlights|Bundled'
//   build/release/tests/saltus_benchmarks --benchmark_filter=AthleteFamily
//   build/release/tests/saltus_benchmarks --benchmark_filter=OneMotionOnTheFamily/6/   (M7 alone)
//   build/release/tests/saltus_benchmarks --benchmark_filter=CostAgainstFlightLength
// The smoke run in ctest leaves these out.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "saltus/base/text_format.h"
#include "saltus/evaluation/joint_loads.h"
#include "saltus/evaluation/simulate.h"
#include "saltus/evaluation/yeadon_angles.h"
#include "saltus/formats/model_file.h"
#include "saltus/formats/motion_file.h"
#include "saltus/optim/optimize.h"
#include "saltus/studies/exact_flights.h"
#include "saltus/use_cases/athlete_models.h"
#include "support/athlete_family.h"

namespace saltus {
namespace {

double percentile(std::vector<double> values, double p) {
  std::sort(values.begin(), values.end());
  const double at = p * (values.size() - 1);
  const std::size_t low = static_cast<std::size_t>(std::floor(at));
  const std::size_t high = std::min(values.size() - 1, low + 1);
  return values[low] + (at - low) * (values[high] - values[low]);
}

/// Seeds 1..N of a family (N = the first argument) as generated (second argument 0) or with
/// their interior times moved by up to ±0.1 s. Counters: cases, solved, the share at or below
/// 0.5 N, the median and worst true residual (N), the median and 95th-percentile wall time (s)
/// and the median wall time per second of flight, the worst angle between the free flight of the
/// optimised motion and the optimised motion itself at landing (°) and, with moved times, how
/// much of the total timing error the optimisation removed (%): over the family, and the mean of
/// each flight's own cut; and the joint loads: the largest rise of a joint's peak load against
/// the interpolated input's (evaluation/joint_loads.h), median and worst, and the share of
/// flights where no joint's peak rose past 1.5× (the others are named in the label).
void sweep_family(benchmark::State& bench, ExactFlight (*make)(const BodyModel&, std::uint64_t)) {
  const int count = static_cast<int>(bench.range(0));
  const bool moved = bench.range(1) != 0;
  const BodyModel model =
      load_body_model(std::string(SALTUS_RESOURCES_DIR) + "/models/zatsiorsky-66kg.json");
  for (auto _ : bench) {
    std::vector<double> forces, seconds, per_flight_second, joint_rises;
    int solved = 0, near_zero = 0;
    double error_before = 0.0, error_after = 0.0, cut_sum = 0.0, worst_landing = 0.0,
           worst_landing_near_zero = 0.0;
    int cut_count = 0;
    std::string above_bar;  // the flights with a joint past 1.5x, for the label
    for (int seed = 1; seed <= count; ++seed) {
      const ExactFlight f = make(model, static_cast<std::uint64_t>(seed));
      const Motion motion =
          moved ? disturb_interior_times(f.motion, 0.1, static_cast<std::uint64_t>(seed))
                : f.motion;
      const auto start = std::chrono::steady_clock::now();
      const OptimizationResult r = optimize_motion(motion, model, {});
      seconds.push_back(
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
      per_flight_second.push_back(seconds.back() / motion.flight_time());
      const double force = r.after.metrics.avg_root_force;
      forces.push_back(force);
      joint_rises.push_back(largest_joint_load_rise(model, r.before.check, r.after.check).ratio());
      if (joint_rises.back() > 1.5)
        above_bar += (above_bar.empty() ? "seed " : ", seed ") + std::to_string(seed) + " " +
                     format_number("%.2fx", joint_rises.back());
      solved += r.solve.solved;
      near_zero += r.solve.solved && force <= 0.5;
      const double landing = simulate_motion(r.optimized_motion, model).landing_vs_motion_deg;
      worst_landing = std::max(worst_landing, landing);
      if (r.solve.solved && force <= 0.5)
        worst_landing_near_zero = std::max(worst_landing_near_zero, landing);
      double before = 0.0, after = 0.0;
      for (std::size_t i = 0; i < motion.keyframes.size(); ++i) {
        before += std::abs(motion.keyframes[i].time - f.motion.keyframes[i].time);
        after += std::abs(r.after.keyframe_times[i] - f.motion.keyframes[i].time);
      }
      error_before += before;
      error_after += after;
      if (before > 0) {
        cut_sum += 1.0 - after / before;
        ++cut_count;
      }
    }
    bench.counters["cases"] = count;
    bench.counters["solved"] = solved;
    bench.counters["at_most_0.5N_pct"] = 100.0 * near_zero / count;
    bench.counters["median_N"] = percentile(forces, 0.5);
    bench.counters["worst_N"] = *std::max_element(forces.begin(), forces.end());
    bench.counters["median_s"] = percentile(seconds, 0.5);
    bench.counters["p95_s"] = percentile(seconds, 0.95);
    bench.counters["median_s_per_flight_s"] = percentile(per_flight_second, 0.5);
    bench.counters["worst_landing_vs_motion_deg"] = worst_landing;
    // The flights the optimiser made physical (solved, at most 0.5 N): issue 24's 3° bar.
    bench.counters["worst_landing_at_most_0.5N_deg"] = worst_landing_near_zero;
    bench.counters["median_joint_rise"] = percentile(joint_rises, 0.5);
    bench.counters["worst_joint_rise"] = *std::max_element(joint_rises.begin(), joint_rises.end());
    bench.counters["joint_rise_at_most_1.5_pct"] =
        100.0 *
        std::count_if(joint_rises.begin(), joint_rises.end(), [](double r) { return r <= 1.5; }) /
        count;
    if (!above_bar.empty()) bench.SetLabel("joints above 1.5x: " + above_bar);
    if (moved) {
      bench.counters["timing_error_cut_pct"] = 100.0 * (1.0 - error_after / error_before);
      bench.counters["mean_flight_cut_pct"] = 100.0 * cut_sum / std::max(1, cut_count);
    }
  }
}

void BM_FamilyOfExactFlights(benchmark::State& bench) {
  sweep_family(bench, make_exact_flight);
}

/// The twisting family (make_twisting_flight): twists from the take-off and from an arm.
void BM_TwistingExactFlights(benchmark::State& bench) {
  sweep_family(bench, make_twisting_flight);
}
BENCHMARK(BM_TwistingExactFlights)
    ->Args({40, 0})
    ->Args({20, 1})
    ->Iterations(1)
    ->Unit(benchmark::kSecond);

/// The hard twisting family (make_hard_twisting_flight): 2-3 twists on 7-11 keyframes, issue
/// 45's held-out kind.
void BM_HardTwistingFlights(benchmark::State& bench) {
  sweep_family(bench, make_hard_twisting_flight);
}
BENCHMARK(BM_HardTwistingFlights)->Args({12, 0})->Iterations(1)->Unit(benchmark::kSecond);

BENCHMARK(BM_FamilyOfExactFlights)
    ->Args({100, 0})
    ->Args({50, 1})
    ->Iterations(1)
    ->Unit(benchmark::kSecond);

/// The bundled motions, sorted by file name (M1 ... M7, then the dive and the aerial full twist).
std::vector<std::filesystem::path> bundled_motions() {
  std::vector<std::filesystem::path> motions;
  for (const auto& entry :
       std::filesystem::directory_iterator(std::string(SALTUS_EXAMPLES_DIR) + "/motions"))
    motions.push_back(entry.path());
  std::sort(motions.begin(), motions.end());
  return motions;
}

/// Each bundled motion, default options: true residual before and after (N), wall time (s).
void BM_BundledMotion(benchmark::State& bench) {
  const std::filesystem::path path = bundled_motions().at(static_cast<std::size_t>(bench.range(0)));
  bench.SetLabel(path.filename().string());
  const MotionFile file = load_motion_file(path.string());
  OptimizationResult r;
  for (auto _ : bench)
    r = optimize_motion(file.motion, file.model, {});
  bench.counters["before_N"] = r.before.metrics.avg_root_force;
  bench.counters["after_N"] = r.after.metrics.avg_root_force;
  bench.counters["iterations"] = r.solve.iterations;
  bench.counters["solved"] = r.solve.solved;
}
BENCHMARK(BM_BundledMotion)->DenseRange(0, 8)->Iterations(3)->Unit(benchmark::kSecond);

/// Issue 24, "cost that grows no faster than the flight": default optimisation of M7 (three
/// runs, the median kept) and of the flights of both exact families (seeds 1..N of the mixed
/// one, first argument, and of the twisting one, second) that fly longer than M7 and somersault
/// at least once. Counters: M7's wall time per second of flight and per somersault (Yeadon's
/// somersaults of the optimised motion), the long flights' medians of the same, and their ratios
/// to M7's: a ratio at most 1 means a long flight costs no more per second or per somersault.
/// Every flight is printed on stderr, so that an expensive one names itself.
void BM_CostAgainstFlightLength(benchmark::State& bench) {
  const std::filesystem::path m7_path = bundled_motions().at(6);
  const MotionFile m7 = load_motion_file(m7_path.string());
  const BodyModel model =
      load_body_model(std::string(SALTUS_RESOURCES_DIR) + "/models/zatsiorsky-66kg.json");
  auto timed = [](const Motion& motion, const BodyModel& body, double& somersaults) {
    const auto start = std::chrono::steady_clock::now();
    const OptimizationResult r = optimize_motion(motion, body, {});
    const double s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    somersaults = std::abs(yeadon_summary(r.after.trajectory).somersaults);
    return s;
  };
  for (auto _ : bench) {
    std::vector<double> m7_runs;
    double m7_somersaults = 0.0;
    for (int run = 0; run < 3; ++run)
      m7_runs.push_back(timed(m7.motion, m7.model, m7_somersaults));
    const double m7_s = percentile(m7_runs, 0.5);
    const double m7_flight = m7.motion.flight_time();
    std::vector<double> per_second, per_somersault;
    std::fprintf(stderr, "M7: %.2f s flight, %.2f somersaults, %.2f s\n", m7_flight, m7_somersaults,
                 m7_s);
    auto sweep = [&](ExactFlight (*make)(const BodyModel&, std::uint64_t), int count) {
      for (int seed = 1; seed <= count; ++seed) {
        const ExactFlight f = make(model, static_cast<std::uint64_t>(seed));
        const double flight = f.motion.flight_time();
        if (flight <= m7_flight || std::abs(f.somersaults) < 1.0) continue;
        double somersaults = 0.0;
        const double s = timed(f.motion, model, somersaults);
        per_second.push_back(s / flight);
        per_somersault.push_back(s / std::max(somersaults, 1.0));
        std::fprintf(stderr, "%s: %.2f s, %.2f s per s of flight, %.2f per somersault\n",
                     f.description().c_str(), s, per_second.back(), per_somersault.back());
      }
    };
    sweep(make_exact_flight, static_cast<int>(bench.range(0)));
    sweep(make_twisting_flight, static_cast<int>(bench.range(1)));
    const double m7_per_second = m7_s / m7_flight, m7_per_somersault = m7_s / m7_somersaults;
    bench.counters["m7_s"] = m7_s;
    bench.counters["m7_s_per_flight_s"] = m7_per_second;
    bench.counters["m7_s_per_somersault"] = m7_per_somersault;
    bench.counters["long_flights"] = static_cast<double>(per_second.size());
    if (per_second.empty()) continue;
    const double long_per_second = percentile(per_second, 0.5);
    const double long_per_somersault = percentile(per_somersault, 0.5);
    bench.counters["long_median_s_per_flight_s"] = long_per_second;
    bench.counters["long_median_s_per_somersault"] = long_per_somersault;
    bench.counters["per_flight_s_vs_m7"] = long_per_second / m7_per_second;
    bench.counters["per_somersault_vs_m7"] = long_per_somersault / m7_per_somersault;
    bench.counters["worst_per_flight_s_vs_m7"] =
        *std::max_element(per_second.begin(), per_second.end()) / m7_per_second;
  }
}
BENCHMARK(BM_CostAgainstFlightLength)->Args({100, 40})->Iterations(1)->Unit(benchmark::kSecond);

/// Issue 25, "any athlete": every bundled motion flown by every athlete of the seeded family
/// (support/athlete_family.h: 8 of de Leva's people, 4 perturbed measured men), its take-off
/// carried over with the same spin, default options. Counters: runs (members × motions), the
/// share solved and the share solved at or below 0.5 N true residual (the dense check), the
/// median and worst true residual (N), the worst landing drift (the optimised motion's own free
/// flight against it at landing, °: issue 24's bar is 3°) and how many runs pass it, and the
/// median and worst wall time (s), and the joint loads against the athlete's own interpolated
/// input: how many polishes were kept, the median and worst largest rise and how many runs stay
/// within 1.5x. Each run is printed on stderr as it ends, with the optimiser's status, its
/// levels' drift and the polish's tries, so that a failure names its motion and athlete.
void fly_family(benchmark::State& bench, const std::vector<std::filesystem::path>& motions) {
  const std::vector<test::FamilyMember>& members = test::athlete_family().members;
  for (auto _ : bench) {
    std::vector<double> forces, seconds, drifts, joint_rises;
    int solved = 0, near_zero = 0, drift_above_3 = 0, polish_kept = 0;
    std::fprintf(stderr, "%-54s %-12s %6s %6s %-6s %9s %9s %8s %7s  %s  %s\n", "motion", "athlete",
                 "m", "kg", "solved", "before_N", "after_N", "drift_deg", "s", "status",
                 "levels' drift (deg), polish tries, largest joint rise");
    for (const std::filesystem::path& motion : motions) {
      for (const test::FamilyMember& member : members) {
        const MotionFile file =
            load_motion_for_athlete(motion.string(), member.path, TakeoffRule::kSameSpin);
        const auto start = std::chrono::steady_clock::now();
        const OptimizationResult r = optimize_motion(file.motion, file.model, OptimizeOptions{});
        seconds.push_back(
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        const double force = r.after.check.metrics.avg_root_force;
        const double drift = simulate_motion(r.optimized_motion, file.model).landing_vs_motion_deg;
        forces.push_back(force);
        drifts.push_back(drift);
        joint_rises.push_back(
            largest_joint_load_rise(file.model, r.before.check, r.after.check).ratio());
        const bool kept = r.joint_load_polish && r.joint_load_polish->kept;
        polish_kept += kept;
        solved += r.solve.solved;
        near_zero += r.solve.solved && force <= 0.5;
        drift_above_3 += drift > 3.0;
        // Where a landing or a joint was lost: each level's drift, the polish's last step on its
        // ladder (how many bounded steps it skipped, whether it was kept), the largest joint rise.
        std::string levels;
        for (const OptimizationResult::Level& level : r.levels)
          levels +=
              (levels.empty() ? "" : "/") + std::to_string(std::lround(level.landing_drift_deg));
        if (r.joint_load_polish)
          levels +=
              ", " + std::to_string(r.joint_load_polish->attempts) +
              (r.joint_load_polish->bounded_tries_skipped > 0
                   ? " (" + std::to_string(r.joint_load_polish->bounded_tries_skipped) + " skipped)"
                   : "") +
              (kept ? "" : " not kept");
        levels += ", joints " + format_number("%.2f", joint_rises.back()) + "x";
        std::fprintf(stderr, "%-54s %-12s %6.3f %6.1f %-6s %9.4f %9.4f %8.2f %7.2f  %s  %s\n",
                     motion.filename().string().c_str(), member.model.name.c_str(),
                     standing_body(member.model).height(), member.model.total_mass(),
                     r.solve.solved ? "yes" : "no", r.before.check.metrics.avg_root_force, force,
                     drift, seconds.back(), r.solve.status.c_str(), levels.c_str());
      }
    }
    const double runs = static_cast<double>(forces.size());
    bench.counters["runs"] = runs;
    bench.counters["solved_pct"] = 100.0 * solved / runs;
    bench.counters["at_most_0.5N_pct"] = 100.0 * near_zero / runs;
    bench.counters["median_N"] = percentile(forces, 0.5);
    bench.counters["worst_N"] = *std::max_element(forces.begin(), forces.end());
    bench.counters["worst_landing_deg"] = *std::max_element(drifts.begin(), drifts.end());
    bench.counters["landing_above_3deg"] = drift_above_3;
    bench.counters["median_s"] = percentile(seconds, 0.5);
    bench.counters["worst_s"] = *std::max_element(seconds.begin(), seconds.end());
    // Joint loads against the athlete's own interpolated input (issue 24's 1.5x bar).
    bench.counters["polish_kept"] = polish_kept;
    bench.counters["median_joint_rise"] = percentile(joint_rises, 0.5);
    bench.counters["worst_joint_rise"] = *std::max_element(joint_rises.begin(), joint_rises.end());
    bench.counters["joint_rise_at_most_1.5"] = static_cast<double>(
        std::count_if(joint_rises.begin(), joint_rises.end(), [](double r) { return r <= 1.5; }));
  }
}

void BM_AthleteFamily(benchmark::State& bench) {
  fly_family(bench, bundled_motions());
}
BENCHMARK(BM_AthleteFamily)->Iterations(1)->Unit(benchmark::kSecond);

/// One bundled motion (by its place in bundled_motions(): 5 is M6, 6 M7, 7 the dive) on the
/// whole family, the same counters: `--benchmark_filter=OneMotionOnTheFamily/5/`.
void BM_OneMotionOnTheFamily(benchmark::State& bench) {
  fly_family(bench, {bundled_motions().at(static_cast<std::size_t>(bench.range(0)))});
}
BENCHMARK(BM_OneMotionOnTheFamily)->DenseRange(0, 7)->Iterations(1)->Unit(benchmark::kSecond);

}  // namespace
}  // namespace saltus
