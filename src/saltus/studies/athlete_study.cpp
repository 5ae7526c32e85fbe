#include "saltus/studies/athlete_study.h"

#include <vector>

#include "saltus/body/mass_properties.h"
#include "saltus/evaluation/joint_loads.h"
#include "saltus/evaluation/simulate.h"
#include "saltus/evaluation/yeadon_angles.h"

namespace saltus {

namespace {

/// Yeadon's counts of a simulated flight, from its root rotations.
YeadonSummary flight_turns(const SimulationResult& flight) {
  std::vector<Eigen::Quaterniond> roots;
  roots.reserve(flight.samples.size());
  for (const SampleRecord& sample : flight.samples)
    roots.push_back(sample.segment_rotation.at(0));
  return yeadon_summary(roots);
}

}  // namespace

AthleteOutcome run_athlete_case(const MotionFile& file, const OptimizeOptions& options) {
  AthleteOutcome o;
  o.athlete = file.model.name;
  o.takeoff = file.takeoff_adaptation ? file.takeoff_adaptation->rule : "own model";
  o.mass_kg = file.model.total_mass();
  o.height_m = standing_body(file.model).height();

  // The free flights are the motion's own, whatever the optimiser's resolution: `saltus
  // simulate`'s defaults with the study's time grid.
  EvaluateOptions flight_options;
  flight_options.samples = options.nlp.samples;
  const SimulationResult given = simulate_motion(file.motion, file.model, flight_options);
  o.takeoff_angular_momentum = given.angular_momentum;
  o.landing_error_before_deg = given.landing_root_error_deg;
  const YeadonSummary given_turns = flight_turns(given);
  o.somersaults_before = given_turns.somersaults;
  o.twists_before = given_turns.twists;

  const OptimizationResult result = optimize_motion(file.motion, file.model, options);
  o.status = result.solve.status;
  o.solved = result.solve.solved;
  o.iterations = result.solve.iterations;
  o.seconds = result.solve.seconds;
  o.avg_root_force_before_N = result.before.metrics.avg_root_force;
  o.avg_root_force_after_N = result.after.metrics.avg_root_force;
  o.max_root_force_after_N = result.after.metrics.max_force_N;

  const SimulationResult optimized =
      simulate_motion(result.optimized_motion, file.model, flight_options);
  o.landing_error_after_deg = optimized.landing_root_error_deg;
  const YeadonSummary optimized_turns = flight_turns(optimized);
  o.somersaults_after = optimized_turns.somersaults;
  o.twists_after = optimized_turns.twists;

  // Segment 0's peak is the root wrench, not a joint's load.
  const std::vector<JointLoadPeak>& peaks = result.after.check.joint_peaks;
  for (int k = 1; k < file.model.size() && k < static_cast<int>(peaks.size()); ++k) {
    if (peaks[k].moment_Nm > o.peak_moment_Nm) {
      o.peak_moment_Nm = peaks[k].moment_Nm;
      o.peak_moment_joint = file.model.segments[k].joint;
    }
    if (peaks[k].force_N > o.peak_force_N) {
      o.peak_force_N = peaks[k].force_N;
      o.peak_force_joint = file.model.segments[k].joint;
    }
  }
  o.peak_force_pct_bw = 100.0 * o.peak_force_N / body_weight_N(file.model);
  const JointLoadRise rise =
      largest_joint_load_rise(file.model, result.before.check, result.after.check);
  o.joint_rise_joint = rise.joint;
  o.joint_rise = rise.ratio();
  return o;
}

}  // namespace saltus
