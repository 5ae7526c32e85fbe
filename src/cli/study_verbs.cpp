#include "study_verbs.h"

#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "flags/option_flags.h"
#include "saltus/base/input_error.h"
#include "saltus/base/text_format.h"
#include "saltus/formats/convergence_files.h"
#include "saltus/formats/mass_files.h"
#include "saltus/formats/motion_file.h"
#include "saltus/formats/paper_report_files.h"
#include "saltus/formats/slurm_script.h"
#include "saltus/formats/study_folder.h"
#include "saltus/formats/study_progress.h"
#include "saltus/studies/mass_study.h"
#include "saltus/use_cases/athletes_run.h"
#include "saltus/use_cases/captures.h"
#include "saltus/use_cases/convergence_run.h"
#include "saltus/use_cases/paper_report_run.h"
#include "saltus/use_cases/result_folders.h"
#include "saltus/use_cases/study_runner.h"

namespace saltus::cli {

// Outside the anonymous namespace: StudyVerbs::State holds them.
/// Settings shared by the study verbs and the report: the time grid and the iteration limit of
/// every optimisation they run (option table).
struct StudyArgs {
  std::string out_dir;
  bool quiet = false;
  OptionFlags options;
};

/// How a study runs: processes, shards, resuming, a Slurm array instead.
struct RunArgs {
  int jobs = available_cpus();
  std::string shard;
  bool resume = false;
  double case_time_limit_s = kDefaultCaseTimeLimitS;
  std::string emit_slurm;
  int shards = 0;
  bool no_early_stop = false;
};

namespace {

constexpr int kExitNotSolved = 3;  ///< also: some case of a study crashed or timed out

std::string absolute(const std::string& path) {
  return std::filesystem::absolute(path).lexically_normal().string();
}

void add_study_common(CLI::App* cmd, StudyArgs& args) {
  cmd->add_option("--out", args.out_dir, "output folder (replaced if it holds an earlier result)")
      ->required();
  args.options.add(cmd, {"samples", "max_iterations"});
  cmd->add_flag("--quiet,-q", args.quiet, "print nothing on success");
}

OptimizeOptions study_optimize_options(const StudyArgs& args) {
  OptimizeOptions o = args.options.values().optimize_options();
  // The studies reproduce the paper's protocol at its resolution (knots at the keyframes).
  use_paper_protocol(o);
  return o;
}

void add_run_options(CLI::App* cmd, RunArgs& args) {
  cmd->add_option("--jobs,-j", args.jobs,
                  "cases run at once, each in a process of its own (default: the CPUs this "
                  "process may use); the results do not depend on it")
      ->capture_default_str();
  cmd->add_option("--shard", args.shard,
                  "run only shard I of N (the cases whose index modulo N is I-1) into --out; "
                  "combine the shards with `saltus study merge`");
  cmd->add_flag("--resume", args.resume,
                "continue an interrupted run (OUT.partial): run only the cases it lacks");
  cmd->add_option("--case-time-limit", args.case_time_limit_s,
                  "seconds after which a case's process is killed and the case recorded as "
                  "timed out (0 = none)")
      ->capture_default_str();
  cmd->add_option("--emit-slurm", args.emit_slurm,
                  "write a Slurm job-array script for this study (one array task per shard, "
                  "--shards of them) instead of running it");
  cmd->add_option("--shards", args.shards, "array tasks of --emit-slurm");
  std::string checkpoints;
  for (const FeasibilityCheckpoint& c : kStrictStudyCheckpoints)
    checkpoints += (checkpoints.empty() ? "" : ", ") + format_number("%g", c.violation) +
                   " by iteration " + std::to_string(c.iterations);
  cmd->add_flag("--no-early-stop", args.no_early_stop,
                "run every strict case to its iteration limit (by default a strict run whose "
                "constraint violation has not come below " +
                    checkpoints + " stops as stopped_infeasible)");
}

/// One line per finished case on stderr (formats/study_progress.h: the app reads it back).
void print_progress(const StudyProgress& p) {
  std::fprintf(stderr, "%s\n", study_progress_line(p).c_str());
}

/// The command line again without the options that say how and where it runs, for a Slurm
/// array task (which adds its own --shard, --out, --resume and --jobs).
std::vector<std::string> repeatable_arguments(int argc, char** argv) {
  const std::vector<std::string> with_value{"--out",   "--jobs",       "-j",
                                            "--shard", "--emit-slurm", "--shards"};
  std::vector<std::string> kept;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--resume") continue;
    bool drop = false;
    for (const std::string& option : with_value) {
      if (a == option) {
        drop = true;
        ++i;  // and its value
        break;
      }
      if (a.rfind(option + "=", 0) == 0) {
        drop = true;
        break;
      }
    }
    if (!drop) kept.push_back(a);
  }
  return kept;
}

std::string executable_path(const char* argv0) {
  std::error_code error;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
  return error ? absolute(argv0) : self.string();
}

}  // namespace

struct StudyVerbs::State {
  int argc = 0;
  char** argv = nullptr;

  CLI::App* convergence = nullptr;
  CLI::App* mass = nullptr;
  CLI::App* athletes = nullptr;
  CLI::App* merge = nullptr;
  CLI::App* paper = nullptr;

  struct Convergence {
    StudyArgs common;
    RunArgs run;
    std::vector<std::string> motions;
    std::vector<double> epsilons{10, 50, 100, 500};
    std::vector<double> mass_errors_percent{-20, -10, 0, 10, 20};
    std::vector<std::string> mass_segments{"all"};
    std::vector<double> timing_errors{0, 0.05, 0.1};
    unsigned seed = 1;
  } convergence_args;

  struct Mass {
    StudyArgs common;
    std::string motion;
    std::vector<std::string> scaled_segments{"thigh_l", "thigh_r"};
    double factor = 1.5;
    std::vector<std::string> load_segments{"thigh_r", "upper_arm_r"};
    bool paper_protocol = false;
  } mass_args;

  struct Athletes {
    StudyArgs common;
    RunArgs run;
    std::string motion;
    std::vector<std::string> models;
    std::string takeoff = "same-spin";
  } athletes_args;

  struct Merge {
    std::vector<std::string> inputs;
    std::string out_dir;
    bool quiet = false;
  } merge_args;

  struct Paper {
    StudyArgs common;
    RunArgs run;
    std::string motions_dir;
    bool quick = false;
  } paper_args;

  /// Runs (or emits) the study; prints progress, then `done` on success.
  int run_job(const StudyJob& job, const StudyArgs& common, const RunArgs& run,
              const std::function<void(const StudyRunResult&)>& done) const;
  int run_convergence() const;
  int run_mass() const;
  int run_athletes() const;
  int run_merge() const;
  int run_paper() const;
};

StudyVerbs::StudyVerbs(CLI::App& app, int argc, char** argv) : state_(std::make_unique<State>()) {
  State& s = *state_;
  s.argc = argc;
  s.argv = argv;
  CLI::App* study = app.add_subcommand(
      "study",
      "The paper's experiments: the convergence study (§3.4) and the mass study (§6.1); one "
      "motion on several athletes; merging a study's shards");
  study->require_subcommand(1);

  auto& c = s.convergence_args;
  s.convergence = study->add_subcommand(
      "convergence",
      "Relaxed vs strict model (several ε) under mass-parameter and keyframe-timing errors: "
      "success rate, iterations, time and residual; writes convergence.csv and convergence.md");
  s.convergence
      ->add_option("MOTIONS", c.motions, "motion files (*.motion.json) or captures (*.bvh)")
      ->required();
  add_study_common(s.convergence, c.common);
  s.convergence->add_option("--epsilons", c.epsilons, "strict model's bounds to try, N or N·m")
      ->delimiter(',')
      ->capture_default_str();
  s.convergence
      ->add_option("--mass-errors", c.mass_errors_percent,
                   "mass and inertia errors to try, percent (-20 = 20 % too small)")
      ->delimiter(',')
      ->capture_default_str();
  s.convergence
      ->add_option("--mass-segments", c.mass_segments,
                   "where the mass error goes: 'all' segments and/or segment names (thigh_r, ...)")
      ->delimiter(',')
      ->capture_default_str();
  s.convergence
      ->add_option("--timing-errors", c.timing_errors,
                   "keyframe-time errors to try, s (interior times moved by ±the amount)")
      ->delimiter(',')
      ->capture_default_str();
  s.convergence->add_option("--seed", c.seed, "seed of the timing errors' signs")
      ->capture_default_str();
  add_run_options(s.convergence, c.run);

  auto& m = s.mass_args;
  s.mass = study->add_subcommand(
      "mass",
      "The motion optimised with the model's mass parameters and with some segments scaled "
      "(default: thighs +50 %); joint loads over time in mass.csv, a summary in mass.md with "
      "each load's peak against the peak the interpolated input needs on the same model");
  s.mass->add_option("MOTION", m.motion, "motion file (*.motion.json) or capture (*.bvh)")
      ->required();
  add_study_common(s.mass, m.common);
  s.mass->add_option("--scale", m.scaled_segments, "segments whose mass and inertia are scaled")
      ->delimiter(',')
      ->capture_default_str();
  s.mass->add_option("--factor", m.factor, "mass and inertia multiplier")->capture_default_str();
  s.mass->add_option("--loads", m.load_segments, "segments whose joint loads are written")
      ->delimiter(',')
      ->capture_default_str();
  s.mass->add_flag("--paper-protocol", m.paper_protocol,
                   "optimise at the paper's resolution (knots at the keyframes, no keyframe "
                   "prior) instead of optimize's: its joints pay for the root force with "
                   "loads many times the input's");

  auto& t = s.athletes_args;
  s.athletes = study->add_subcommand(
      "athletes",
      "One motion on several athletes (the motion's own model first): root force before and "
      "after optimisation, the free flight's landing error, somersaults and twists, peak joint "
      "loads, mass, height and take-off L; writes athletes.md and athletes.csv");
  s.athletes->add_option("MOTION", t.motion, "motion file (*.motion.json) or capture (*.bvh)")
      ->required();
  s.athletes
      ->add_option("--models", t.models,
                   "the athletes: model files (*.model.json, `saltus model new|yeadon|scale`) or "
                   "bundled model names")
      ->required();
  s.athletes
      ->add_option("--out", t.common.out_dir,
                   "output folder (replaced if it holds an earlier result)")
      ->required();
  // Every optimiser option, as `saltus optimize` takes them: an athlete's row is what `saltus
  // optimize MOTION --model A` would give.
  t.common.options.add(s.athletes, all_option_names());
  s.athletes->add_flag("--quiet,-q", t.common.quiet, "print nothing on success");
  s.athletes
      ->add_option("--takeoff", t.takeoff,
                   "how the take-off carries over to each athlete: same-spin (the same whole-body "
                   "angular velocity, L follows the inertia) or keep-momentum (the same L)")
      ->capture_default_str();
  add_run_options(s.athletes, t.run);

  auto& g = s.merge_args;
  s.merge = study->add_subcommand(
      "merge",
      "Combine the shards of a study (`--shard I/N` runs, a Slurm array's or GNU parallel's) "
      "into exactly the folder one run of it writes");
  s.merge->add_option("DIRS", g.inputs, "shard folders of one study")->required();
  s.merge->add_option("--out", g.out_dir, "output folder (replaced if it holds an earlier result)")
      ->required();
  s.merge->add_flag("--quiet,-q", g.quiet, "print nothing on success");

  auto& p = s.paper_args;
  s.paper = app.add_subcommand(
      "paper",
      "Reproduce the paper's experiments on M1-M7 and the dive: Table 1 next to the paper's, the "
      "mass and convergence studies, all in report.md");
  s.paper
      ->add_option("MOTIONS_DIR", p.motions_dir,
                   "folder with M1-…M7-….motion.json and dive-….motion.json (examples/motions)")
      ->required();
  add_study_common(s.paper, p.common);
  s.paper->add_flag("--quick", p.quick,
                    "reduced settings: no --knots-per-interval 3 runs, a small convergence study");
  add_run_options(s.paper, p.run);
}

StudyVerbs::~StudyVerbs() = default;

std::optional<int> StudyVerbs::run() const {
  const State& s = *state_;
  if (s.convergence->parsed()) return s.run_convergence();
  if (s.mass->parsed()) return s.run_mass();
  if (s.athletes->parsed()) return s.run_athletes();
  if (s.merge->parsed()) return s.run_merge();
  if (s.paper->parsed()) return s.run_paper();
  return std::nullopt;
}

int StudyVerbs::State::run_job(const StudyJob& job, const StudyArgs& common, const RunArgs& run,
                               const std::function<void(const StudyRunResult&)>& done) const {
  if (!run.emit_slurm.empty()) {
    if (run.shards < 1)
      throw InputError("--emit-slurm", "", "give the number of array tasks with --shards N");
    if (!run.shard.empty())
      throw InputError("--shard", "", "the Slurm array chooses the shards; leave --shard out");
    SlurmArrayScript script;
    script.executable = executable_path(argv[0]);
    script.arguments = repeatable_arguments(argc, argv);
    script.working_dir = std::filesystem::current_path().string();
    script.out_dir = common.out_dir;
    script.shards = run.shards;
    // --jobs only when given: the emitting machine's core count says nothing of a node's.
    bool jobs_given = false;
    for (int i = 1; i < argc; ++i) {
      const std::string a = argv[i];
      jobs_given |= a == "--jobs" || a == "-j" || a.rfind("--jobs=", 0) == 0;
    }
    script.cpus_per_task = jobs_given ? run.jobs : 1;
    write_slurm_array_script(run.emit_slurm, script);
    if (!common.quiet)
      std::printf(
          "saltus: wrote %s, a Slurm array of %d tasks (%zu cases in all)\n  submit: sbatch "
          "%s\n  then:   %s\n",
          absolute(run.emit_slurm).c_str(), run.shards, job.case_names.size(),
          shell_quote(run.emit_slurm).c_str(), slurm_merge_command(script).c_str());
    return 0;
  }
  if (run.shards > 0) throw InputError("--shards", "", "only goes with --emit-slurm");
  StudyRunOptions options;
  options.jobs = run.jobs;
  options.case_time_limit_s = run.case_time_limit_s;
  if (!run.shard.empty()) options.shard = parse_study_shard(run.shard);
  options.resume = run.resume;
  if (!common.quiet) options.progress = print_progress;
  if (!common.quiet)
    std::fprintf(stderr, "saltus: %zu cases%s, %d at a time, each in a process of its own\n",
                 job.case_names.size(),
                 options.shard.whole() ? "" : (", shard " + options.shard.text()).c_str(),
                 options.jobs);
  const StudyRunResult result = run_study(job, common.out_dir, options);
  if (result.interrupt_signal) {
    std::fprintf(stderr,
                 "saltus: interrupted (%s): the finished cases are kept in %s; run the same "
                 "command with --resume to run the others\n",
                 strsignal(result.interrupt_signal), result.partial_dir.c_str());
    // End the way the signal would have ended a program without handlers (docs/safety.md):
    // the shell then knows the run was interrupted, as it does for every other verb.
    std::fflush(nullptr);
    std::signal(result.interrupt_signal, SIG_DFL);
    std::raise(result.interrupt_signal);
    return 128 + result.interrupt_signal;  // a signal that does not end the process
  }
  if (result.already_complete) {
    if (!common.quiet)
      std::printf("saltus: %s already holds this study, complete: nothing to run\n",
                  absolute(common.out_dir).c_str());
    return 0;
  }
  if (!common.quiet) {
    if (options.shard.whole())
      done(result);
    else
      std::printf("saltus: shard %s done (%d cases run, %d failed) in %s\n",
                  options.shard.text().c_str(), result.cases_run, result.failed,
                  absolute(common.out_dir).c_str());
  }
  if (!result.partial_kept.empty()) {
    std::string names;
    for (std::size_t i = 0; i < result.partial_kept.size() && i < 3; ++i)
      names += (i ? ", " : "") + message_text(result.partial_kept[i]);
    if (result.partial_kept.size() > 3) names += ", ...";
    std::fprintf(stderr,
                 "saltus: %s is kept: it holds %zu file(s) Saltus did not write (%s); the "
                 "study's own files there were removed\n",
                 result.partial_dir.c_str(), result.partial_kept.size(), names.c_str());
  }
  if (result.failed > 0) {
    std::fprintf(stderr,
                 "saltus: %d cases did not finish (crashed or timed out); they are recorded as "
                 "failures\n",
                 result.failed);
    return kExitNotSolved;
  }
  return 0;
}

int StudyVerbs::State::run_convergence() const {
  const Convergence& a = convergence_args;
  std::vector<LabelledMotion> motions;
  for (const std::string& path : a.motions)
    motions.push_back({motion_label(path), load_motion_or_capture(path)});
  ConvergenceStudyOptions options;
  options.optimize = study_optimize_options(a.common);
  options.epsilons = a.epsilons;
  options.mass_errors.clear();
  for (double percent : a.mass_errors_percent)
    options.mass_errors.push_back(percent / 100.0);
  options.mass_segments = a.mass_segments;
  options.timing_errors = a.timing_errors;
  options.seed = a.seed;
  if (a.run.no_early_stop) options.strict_checkpoints.clear();
  const StudyJob job = convergence_study_job(motions, options);
  return run_job(job, a.common, a.run, [&](const StudyRunResult& result) {
    const std::string out = absolute(a.common.out_dir);
    std::ifstream md(out + "/convergence.md");
    const std::string text((std::istreambuf_iterator<char>(md)), std::istreambuf_iterator<char>());
    std::printf(
        "saltus study convergence: %zu runs\n\n%s\n  wrote %s/{result.json, convergence.csv, "
        "convergence.md, study.json, cases/}\n",
        result.result.at("cases").size(), text.c_str(), out.c_str());
  });
}

int StudyVerbs::State::run_mass() const {
  const Mass& a = mass_args;
  const MotionFile file = load_motion_or_capture(a.motion);
  MassStudyOptions options;
  options.optimize = a.common.options.values().optimize_options();
  options.paper_protocol = a.paper_protocol;
  options.scaled_segments = a.scaled_segments;
  options.factor = a.factor;
  options.load_segments = a.load_segments;
  const MassStudyResult study = run_mass_study(file, options);
  write_mass_outputs(a.common.out_dir, file, study, options);
  if (!a.common.quiet)
    std::printf(
        "saltus study mass: %s\n\n%s\n  wrote %s/{result.json, mass.csv, mass.md, "
        "model.json, model_scaled.json}\n",
        file.motion.name.c_str(), mass_study_markdown(study).c_str(),
        absolute(a.common.out_dir).c_str());
  return 0;
}

int StudyVerbs::State::run_athletes() const {
  const Athletes& a = athletes_args;
  const OptimizeOptions options = a.common.options.values().optimize_options();
  const StudyJob job = athletes_study_job(a.motion, a.models, a.takeoff, options);
  return run_job(job, a.common, a.run, [&](const StudyRunResult&) {
    const std::string out = absolute(a.common.out_dir);
    std::ifstream md(out + "/athletes.md");
    const std::string text((std::istreambuf_iterator<char>(md)), std::istreambuf_iterator<char>());
    std::printf(
        "saltus study athletes:\n\n%s\n  wrote %s/{result.json, athletes.csv, athletes.md, "
        "study.json, cases/}\n",
        text.c_str(), out.c_str());
  });
}

int StudyVerbs::State::run_merge() const {
  const Merge& a = merge_args;
  const nlohmann::json result = merge_study_folders(a.inputs, a.out_dir);
  if (!a.quiet)
    std::printf("saltus study merge: %zu folders into %s (%s)\n", a.inputs.size(),
                absolute(a.out_dir).c_str(), result.value("format", std::string("?")).c_str());
  return 0;
}

int StudyVerbs::State::run_paper() const {
  const Paper& a = paper_args;
  PaperReportOptions options;
  options.motions_dir = a.motions_dir;
  options.quick = a.quick;
  options.optimize = study_optimize_options(a.common);
  if (a.run.no_early_stop) options.strict_checkpoints.clear();
  const StudyJob job = paper_report_job(options);
  return run_job(job, a.common, a.run, [&](const StudyRunResult&) {
    const std::string out = absolute(a.common.out_dir);
    std::printf(
        "saltus paper: wrote %s/report.md (figures: saltus-gui --export-figures %s/figures "
        "%s/M1 %s/M7 ...)\n",
        out.c_str(), out.c_str(), out.c_str(), out.c_str());
  });
}

}  // namespace saltus::cli
