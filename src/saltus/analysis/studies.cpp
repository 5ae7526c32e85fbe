#include "saltus/analysis/studies.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <map>
#include <random>
#include <sstream>
#include <stdexcept>

namespace saltus {

std::string format_number(const char* pattern, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, pattern, value);
  return buffer;
}

namespace {

double median(std::vector<double> values) {
  if (values.empty()) return std::nan("");
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

std::string mass_label(const StudyCase& c) {
  if (c.mass_error == 0.0) return "0 %";
  return format_number("%+.0f %%", 100.0 * c.mass_error) + " (" + c.mass_segment + ")";
}

std::string timing_label(const StudyCase& c) {
  return c.timing_error_s == 0.0 ? "0 s" : format_number("±%.2f s", c.timing_error_s);
}

/// Success-rate table: one row per value of `row_of`, one column per formulation.
std::string success_table(const std::vector<StudyOutcome>& outcomes, const std::string& heading,
                          const std::function<std::string(const StudyCase&)>& row_of) {
  std::vector<std::string> rows, columns;
  std::map<std::pair<std::string, std::string>, std::pair<int, int>> counts;  // solved, total
  for (const StudyOutcome& o : outcomes) {
    const std::string row = row_of(o.study_case), column = formulation_label(o.study_case);
    if (std::find(rows.begin(), rows.end(), row) == rows.end()) rows.push_back(row);
    if (std::find(columns.begin(), columns.end(), column) == columns.end())
      columns.push_back(column);
    auto& count = counts[{row, column}];
    count.first += o.solved ? 1 : 0;
    count.second += 1;
  }
  std::ostringstream out;
  out << "| " << heading << " |";
  for (const std::string& c : columns)
    out << ' ' << c << " |";
  out << "\n|---|";
  for (std::size_t i = 0; i < columns.size(); ++i)
    out << "---|";
  out << '\n';
  for (const std::string& r : rows) {
    out << "| " << r << " |";
    for (const std::string& c : columns) {
      const auto it = counts.find({r, c});
      if (it == counts.end()) {
        out << " – |";
        continue;
      }
      out << ' ' << it->second.first << '/' << it->second.second << " |";
    }
    out << '\n';
  }
  return out.str();
}

/// Joint wrench (force first) of `segment` at every sample of an evaluation.
const Vector6d& load(const SampleRecord& sample, int segment) {
  return sample.joint_wrench.at(segment);
}

}  // namespace

std::string motion_label(const std::string& path) {
  std::string stem = std::filesystem::path(path).filename().string();
  const std::string suffix = ".motion.json";
  if (stem.size() > suffix.size() &&
      stem.compare(stem.size() - suffix.size(), suffix.size(), suffix) == 0)
    stem.resize(stem.size() - suffix.size());
  if (stem.size() >= 2 && stem[0] == 'M' && std::isdigit(static_cast<unsigned char>(stem[1]))) {
    std::size_t end = 1;
    while (end < stem.size() && std::isdigit(static_cast<unsigned char>(stem[end])))
      ++end;
    return stem.substr(0, end);
  }
  return stem;
}

Motion disturb_keyframe_times(const Motion& motion, double amplitude, unsigned seed,
                              double min_gap_s) {
  Motion out = motion;
  out.spline.reset();  // a stored spline belongs to the old times
  const int n = static_cast<int>(motion.keyframes.size());
  if (n < 3 || amplitude == 0.0) return out;
  const double duration = motion.flight_time();
  // The raw engine output is the same on every platform (distributions are not).
  std::mt19937 engine(seed);
  for (int i = 1; i + 1 < n; ++i) {
    const double sign = (engine() & 1u) ? 1.0 : -1.0;
    double t = motion.keyframes[i].time + sign * amplitude;
    t = std::max(t, out.keyframes[i - 1].time + min_gap_s);
    t = std::min(t, duration - (n - 1 - i) * min_gap_s);
    out.keyframes[i].time = t;
  }
  return out;
}

std::vector<StudyCase> convergence_study_cases(const std::vector<LabelledMotion>& motions,
                                               const ConvergenceStudyOptions& options) {
  std::vector<std::pair<Formulation, double>> formulations{{Formulation::kRelaxed, 0.0}};
  for (double e : options.epsilons)
    formulations.emplace_back(Formulation::kStrict, e);
  std::vector<std::pair<std::string, double>> masses;
  bool nominal = false;
  for (const std::string& segment : options.mass_segments)
    for (double error : options.mass_errors) {
      if (error == 0.0) {
        if (!nominal) masses.emplace_back("all", 0.0);
        nominal = true;
      } else {
        masses.emplace_back(segment, error);
      }
    }
  std::vector<StudyCase> cases;
  for (const LabelledMotion& m : motions)
    for (const auto& [formulation, epsilon] : formulations)
      for (const auto& [segment, error] : masses)
        for (double timing : options.timing_errors) {
          StudyCase c;
          c.motion = m.label;
          c.formulation = formulation;
          c.epsilon = epsilon;
          c.mass_segment = segment;
          c.mass_error = error;
          c.timing_error_s = timing;
          cases.push_back(c);
        }
  return cases;
}

StudyOutcome run_study_case(const LabelledMotion& motion, const StudyCase& study_case,
                            const ConvergenceStudyOptions& options) {
  const Motion disturbed =
      disturb_keyframe_times(motion.file.motion, study_case.timing_error_s, options.seed);
  BodyModel model = motion.file.model;
  if (study_case.mass_error != 0.0) {
    const std::string segment = study_case.mass_segment == "all" ? "" : study_case.mass_segment;
    model = scale_segment_mass(model, segment, 1.0 + study_case.mass_error);
  }
  OptimizeOptions optimize = options.optimize;
  optimize.nlp.formulation = study_case.formulation;
  if (study_case.formulation == Formulation::kStrict) optimize.nlp.epsilon = study_case.epsilon;
  const OptimizationResult r = optimize_motion(disturbed, model, optimize);
  StudyOutcome o;
  o.study_case = study_case;
  o.status = r.solve.status;
  o.solved = r.solve.solved;
  o.iterations = r.solve.iterations;
  o.seconds = r.solve.seconds;
  o.variables = r.variables;
  o.constraints = r.constraints;
  o.avg_force_before = r.before.metrics.avg_root_force;
  o.avg_force_after = r.after.metrics.avg_root_force;
  o.max_force_after = r.after.metrics.max_force_N;
  o.max_quaternion_error = r.after.keyframe_errors.max_quaternion_error;
  o.knots_per_interval = r.knots_per_interval;
  o.restarts = r.solve.restarts;
  return o;
}

std::vector<StudyOutcome> run_convergence_study(
    const std::vector<LabelledMotion>& motions, const ConvergenceStudyOptions& options,
    const std::function<void(int, int, const StudyOutcome&)>& progress) {
  const std::vector<StudyCase> cases = convergence_study_cases(motions, options);
  std::vector<StudyOutcome> outcomes;
  outcomes.reserve(cases.size());
  for (const StudyCase& c : cases) {
    const auto motion = std::find_if(motions.begin(), motions.end(),
                                     [&](const LabelledMotion& m) { return m.label == c.motion; });
    outcomes.push_back(run_study_case(*motion, c, options));
    if (progress)
      progress(static_cast<int>(outcomes.size()), static_cast<int>(cases.size()), outcomes.back());
  }
  return outcomes;
}

std::string formulation_label(const StudyCase& study_case) {
  if (study_case.formulation == Formulation::kRelaxed) return "relaxed";
  return format_number("strict ε=%g", study_case.epsilon);
}

std::string convergence_markdown(const std::vector<StudyOutcome>& outcomes) {
  std::ostringstream out;
  // Summary per formulation, in order of first appearance.
  std::vector<std::string> labels;
  for (const StudyOutcome& o : outcomes) {
    const std::string label = formulation_label(o.study_case);
    if (std::find(labels.begin(), labels.end(), label) == labels.end()) labels.push_back(label);
  }
  out << "| model | cases | solved | median iterations | median time (s) | median avg root force "
         "after (N) | worst avg root force after, solved cases (N) |\n"
      << "|---|---|---|---|---|---|---|\n";
  for (const std::string& label : labels) {
    int total = 0, solved = 0;
    std::vector<double> iterations, seconds, force;
    double worst = 0.0;
    for (const StudyOutcome& o : outcomes) {
      if (formulation_label(o.study_case) != label) continue;
      ++total;
      iterations.push_back(o.iterations);
      seconds.push_back(o.seconds);
      force.push_back(o.avg_force_after);
      if (o.solved) {
        ++solved;
        worst = std::max(worst, o.avg_force_after);
      }
    }
    out << "| " << label << " | " << total << " | " << solved << " ("
        << format_number("%.0f", 100.0 * solved / std::max(total, 1)) << " %) | "
        << format_number("%.0f", median(iterations)) << " | "
        << format_number("%.2f", median(seconds)) << " | " << format_number("%.3g", median(force))
        << " | " << (solved ? format_number("%.3g", worst) : std::string("–")) << " |\n";
  }
  // Cases whose interpolation could not meet the keyframes on the requested knots ran refined.
  std::map<std::string, int> refined;
  int requested = std::numeric_limits<int>::max();
  for (const StudyOutcome& o : outcomes)
    requested = std::min(requested, o.knots_per_interval);
  for (const StudyOutcome& o : outcomes)
    if (o.knots_per_interval > requested)
      ++refined[o.study_case.motion + format_number(" at ±%g s", o.study_case.timing_error_s)];
  if (!refined.empty()) {
    out << "\nRun with refined knots (K > " << requested
        << ") because the interpolation on the requested knots missed the keyframes by more than "
           "their tolerance (a turn of more than 180° between control points): ";
    bool first = true;
    for (const auto& [where, count] : refined) {
      out << (first ? "" : ", ") << where << " (" << count << " cases)";
      first = false;
    }
    out << ".\n";
  }
  out << "\nSolved cases by motion:\n\n"
      << success_table(outcomes, "motion", [](const StudyCase& c) { return c.motion; })
      << "\nSolved cases by mass-parameter error (masses and inertias scaled; segment in "
         "brackets):\n\n"
      << success_table(outcomes, "mass error", mass_label)
      << "\nSolved cases by keyframe-timing error (interior times moved by ± the amount, signs "
         "seeded):\n\n"
      << success_table(outcomes, "timing error", timing_label);
  return out.str();
}

std::string convergence_csv(const std::vector<StudyOutcome>& outcomes) {
  std::ostringstream out;
  out << "motion,formulation,epsilon,mass_segment,mass_error,timing_error_s,status,solved,"
         "iterations,seconds,variables,constraints,avg_force_before_N,avg_force_after_N,"
         "max_force_after_N,max_quaternion_error,knots_per_interval,restarts\n";
  out.precision(10);
  for (const StudyOutcome& o : outcomes) {
    const StudyCase& c = o.study_case;
    out << c.motion << ',' << (c.formulation == Formulation::kRelaxed ? "relaxed" : "strict") << ','
        << c.epsilon << ',' << c.mass_segment << ',' << c.mass_error << ',' << c.timing_error_s
        << ',' << o.status << ',' << (o.solved ? 1 : 0) << ',' << o.iterations << ',' << o.seconds
        << ',' << o.variables << ',' << o.constraints << ',' << o.avg_force_before << ','
        << o.avg_force_after << ',' << o.max_force_after << ',' << o.max_quaternion_error << ','
        << o.knots_per_interval << ',' << o.restarts << '\n';
  }
  return out.str();
}

MassStudyResult run_mass_study(const MotionFile& file, const MassStudyOptions& options) {
  if (!(options.factor > 0)) throw std::invalid_argument("mass factor must be positive");
  MassStudyResult study;
  for (const std::string& s : options.load_segments)
    if (file.model.segment_index(s) < 0)
      throw std::invalid_argument("no segment named '" + s + "' in model " + file.model.name);
  study.load_segments = options.load_segments;

  BodyModel scaled = file.model;
  std::string label;
  for (const std::string& s : options.scaled_segments) {
    if (file.model.segment_index(s) < 0)
      throw std::invalid_argument("no segment named '" + s + "' in model " + file.model.name);
    scaled = scale_segment_mass(scaled, s, options.factor);
    label += (label.empty() ? "" : "+") + s;
  }
  label += format_number(" x%g", options.factor);
  study.runs.push_back({file.model.name, file.model, {}});
  study.runs.push_back({label, scaled, {}});
  for (MassStudyRun& run : study.runs)
    run.result = optimize_motion(file.motion, run.model, options.optimize);
  return study;
}

std::string mass_study_csv(const MassStudyResult& study) {
  std::ostringstream out;
  const char* prefix[] = {"given", "scaled"};
  out << 't';
  for (std::size_t r = 0; r < study.runs.size(); ++r)
    for (const std::string& s : study.load_segments)
      for (const char* q : {"fx", "fy", "fz", "mx", "my", "mz", "force_N", "moment_Nm"})
        out << ',' << prefix[r] << '.' << s << '.' << q;
  out << '\n';
  out.precision(10);
  const std::size_t samples = study.runs.front().result.after.samples.size();
  for (std::size_t k = 0; k < samples; ++k) {
    out << study.runs.front().result.after.samples[k].time;
    for (const MassStudyRun& run : study.runs) {
      const SampleRecord& sample = run.result.after.samples.at(k);
      for (const std::string& s : study.load_segments) {
        const Vector6d& w = load(sample, run.model.segment_index(s));
        for (int i = 0; i < 6; ++i)
          out << ',' << w[i];
        out << ',' << w.head<3>().norm() << ',' << w.tail<3>().norm();
      }
    }
    out << '\n';
  }
  return out.str();
}

std::string mass_study_markdown(const MassStudyResult& study) {
  std::ostringstream out;
  out << "| model | segment | RMS force (N) | peak force (N) | RMS moment (N·m) | peak moment "
         "(N·m) | avg root force after (N) |\n|---|---|---|---|---|---|---|\n";
  std::map<std::string, std::vector<double>> figures;  // segment -> per run RMS force, moment
  for (const MassStudyRun& run : study.runs) {
    for (const std::string& s : study.load_segments) {
      const int index = run.model.segment_index(s);
      double force2 = 0, moment2 = 0, peak_force = 0, peak_moment = 0;
      const auto& samples = run.result.after.samples;
      for (const SampleRecord& sample : samples) {
        const Vector6d& w = load(sample, index);
        force2 += w.head<3>().squaredNorm();
        moment2 += w.tail<3>().squaredNorm();
        peak_force = std::max(peak_force, w.head<3>().norm());
        peak_moment = std::max(peak_moment, w.tail<3>().norm());
      }
      const double n = std::max<std::size_t>(samples.size(), 1);
      const double rms_force = std::sqrt(force2 / n), rms_moment = std::sqrt(moment2 / n);
      figures[s].push_back(rms_force);
      figures[s].push_back(rms_moment);
      out << "| " << run.label << " | " << s << " | " << format_number("%.1f", rms_force) << " | "
          << format_number("%.1f", peak_force) << " | " << format_number("%.2f", rms_moment)
          << " | " << format_number("%.2f", peak_moment) << " | "
          << format_number("%.3g", run.result.after.metrics.avg_root_force) << " |\n";
    }
  }
  if (study.runs.size() == 2) {
    out << "\nScaled / given (RMS):\n\n| segment | force | moment |\n|---|---|---|\n";
    for (const std::string& s : study.load_segments) {
      const std::vector<double>& f = figures[s];
      out << "| " << s << " | " << format_number("%.2f", f[2] / f[0]) << " | "
          << format_number("%.2f", f[3] / f[1]) << " |\n";
    }
  }
  return out.str();
}

}  // namespace saltus
