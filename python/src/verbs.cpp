#include <pybind11/stl.h>

#include <csignal>
#include <utility>

#include "module.h"
#include "saltus/base/text_format.h"
#include "saltus/formats/mass_files.h"
#include "saltus/formats/model_file.h"
#include "saltus/formats/result_json.h"
#include "saltus/formats/study_progress.h"
#include "saltus/studies/mass_study.h"
#include "saltus/use_cases/athlete_models.h"
#include "saltus/use_cases/athletes_run.h"
#include "saltus/use_cases/captures.h"
#include "saltus/use_cases/convergence_run.h"
#include "saltus/use_cases/flag_bounds.h"
#include "saltus/use_cases/motion_exports.h"
#include "saltus/use_cases/paper_report_run.h"
#include "saltus/use_cases/result_folders.h"
#include "saltus/use_cases/study_runner.h"

namespace saltus_python {

namespace {

using saltus::OptionUse;

struct CaptureImport {
  std::shared_ptr<const saltus::CaptureFile> capture;
};

/// A result folder read back (`saltus evaluate`, `simulate` or `optimize`).
struct ResultFolder {
  std::shared_ptr<const saltus::ResultFolder> folder;
  std::shared_ptr<Flight> before, after;
};

/// One of an import's motions on its model, naming the model as the import's files do.
MotionPtr capture_motion(const saltus::CaptureFile& capture, const saltus::Motion& motion) {
  saltus::MotionFile f;
  f.path = capture.path;
  f.model = capture.model;
  f.motion = motion;
  f.motion.model = capture.model_reference;
  return new_motion(f);
}

std::shared_ptr<Flight> csv_flight(std::shared_ptr<const saltus::ResultFolder> folder,
                                   std::shared_ptr<const saltus::BodyModel> model,
                                   const saltus::TrajectoryCsv& csv) {
  auto f = std::make_shared<Flight>();
  f->samples = std::shared_ptr<const std::vector<saltus::SampleRecord>>(folder, &csv.samples);
  f->model = std::move(model);
  f->angles_deg = csv.angles_deg;
  return f;
}

/// Options of the studies other than `study athletes`: the CLI's --samples and --max-iter.
saltus::OptimizeOptions study_options(int samples, int max_iter, bool paper_protocol) {
  saltus::OptionValues values;
  values.set("samples", samples);
  values.set("max_iterations", max_iter);
  saltus::OptimizeOptions o = values.optimize_options();
  if (paper_protocol) saltus::use_paper_protocol(o);
  return o;
}

/// Runs a study's cases in processes of their own into `out` (the study runner), the GIL
/// released; `progress(line)` after every case. Ctrl+C stops it (the finished cases stay in
/// OUT.partial; resume=True goes on) and raises KeyboardInterrupt.
py::dict run_study_job(const saltus::StudyJob& job, const std::string& out, py::object jobs,
                       const std::string& shard, bool resume, double case_time_limit,
                       const py::object& progress) {
  saltus::StudyRunOptions options;
  options.jobs = jobs.is_none() ? saltus::available_cpus() : py::cast<int>(jobs);
  saltus::check_flag("--jobs", options.jobs,
                     "paper");  // every study's --jobs and --case-time-limit
  saltus::check_flag("--case-time-limit", case_time_limit, "paper");
  options.case_time_limit_s = case_time_limit;
  if (!shard.empty()) options.shard = saltus::parse_study_shard(shard, "shard");
  options.resume = resume;
  if (!progress.is_none())
    options.progress = [&progress](const saltus::StudyProgress& p) {
      py::gil_scoped_acquire gil;
      progress(saltus::study_progress_line(p));
    };
  saltus::StudyRunResult result;
  {
    py::gil_scoped_release release;
    result = saltus::run_study(job, out, options);
  }
  if (result.interrupt_signal == SIGINT) {
    PyErr_SetString(PyExc_KeyboardInterrupt,
                    ("the finished cases are kept in " + result.partial_dir +
                     "; run again with resume=True to run the others")
                        .c_str());
    throw py::error_already_set();
  }
  if (result.interrupt_signal != 0)
    throw std::runtime_error("the study was stopped by signal " +
                             std::to_string(result.interrupt_signal) + "; its cases are kept in " +
                             result.partial_dir);
  py::dict d;
  d["result"] = python_json(result.result);
  d["complete"] = result.complete;
  d["already_complete"] = result.already_complete;
  d["cases_run"] = result.cases_run;
  d["failed"] = result.failed;
  return d;
}

std::string list_text(const std::vector<std::string>& words) {
  std::string out;
  for (const std::string& w : words)
    out += (out.empty() ? "'" : ", '") + w + "'";
  return "[" + out + "]";
}

std::string list_text(const std::vector<double>& numbers) {
  std::string out;
  for (double v : numbers)
    out += (out.empty() ? "" : ", ") + saltus::format_number("%.10g", v);
  return "[" + out + "]";
}

/// The convergence study's defaults, its mass errors in percent as the CLI takes them.
std::vector<double> default_mass_errors_percent() {
  std::vector<double> out;
  for (double e : saltus::ConvergenceStudyOptions{}.mass_errors)
    out.push_back(e * 100.0);
  return out;
}

/// "samples=101, max_iter=300": the studies' two options, at the table's defaults.
std::string study_option_parameters() {
  return "samples=" + std::to_string(saltus::kDefaultSamples) +
         ", max_iter=" + std::to_string(saltus::SolverOptions{}.max_iterations);
}

const char* const kRunDoc =
    "jobs: cases at once, each in a process of its own (None: the CPUs this process may use); "
    "shard: 'I/N' runs only shard I of N (study_merge combines them); resume: go on with an "
    "interrupted run's OUT.partial; case_time_limit: seconds after which a case is killed and "
    "recorded as timed out (0: none); progress(line): called after every case with the CLI's "
    "progress line. Ctrl+C stops the study and raises KeyboardInterrupt (finished cases kept). "
    "Returns a dict: result (result.json), complete, already_complete, cases_run, failed (cases "
    "that crashed or timed out).";

}  // namespace

void bind_verbs(py::module_& m) {
  // ---- import and export ----
  py::class_<CaptureImport>(m, "CaptureImport",
                            "A motion capture imported onto a body model (`saltus import`): the "
                            "flight found, its take-off state, the keyframes picked.")
      .def_property_readonly(
          "keyframes",
          [](const CaptureImport& c) {
            return capture_motion(*c.capture, c.capture->import.keyframes);
          },
          "the picked keyframes, a Motion to evaluate or optimise")
      .def_property_readonly(
          "captured",
          [](const CaptureImport& c) {
            return capture_motion(*c.capture, c.capture->import.captured);
          },
          "every captured flight frame as a keyframe, a Motion")
      .def_property_readonly("warnings",
                             [](const CaptureImport& c) { return c.capture->import.warnings; })
      .def_property_readonly(
          "result",
          [](const CaptureImport& c) {
            return python_json(saltus::capture_result_json(*c.capture));
          },
          "result.json of `saltus import`, as a dict")
      .def(
          "write",
          [](const CaptureImport& c, py::handle out) {
            const std::string dir = path_argument(out, "out");
            return write_released([&] { return saltus::write_capture_outputs(dir, *c.capture); });
          },
          py::arg("out"),
          documented(
              "write($self, out)",
              "Writes result.json, capture.motion.json, keyframes.motion.json, trajectory.csv and "
              "model.json atomically.")
              .c_str())
      .def("__repr__", [](const CaptureImport& c) {
        return "<saltus.CaptureImport " + c.capture->path + " onto " + c.capture->model.name +
               ": " + std::to_string(c.capture->import.keyframes.keyframes.size()) + " keyframes>";
      });

  m.def(
      "import_capture",
      [](py::handle path, py::handle model, py::handle mapping, py::handle keyframes,
         py::handle flight, double frame_time) {
        const std::string file = path_argument(path, "path");
        const std::string model_text = model.is_none() ? "" : path_argument(model, "model");
        const std::string mapping_text = mapping.is_none() ? "" : path_argument(mapping, "mapping");
        std::string keyframes_text;
        if (py::isinstance<py::str>(keyframes))
          keyframes_text = py::cast<std::string>(keyframes);
        else if (!keyframes.is_none())
          keyframes_text = py::cast<std::string>(py::str(keyframes));
        std::string flight_text;
        if (!flight.is_none()) {
          const std::vector<double> f = numbers_from(flight, {2}, "flight");
          flight_text =
              saltus::format_number("%.17g", f[0]) + ":" + saltus::format_number("%.17g", f[1]);
        }
        const saltus::CaptureFileOptions options = saltus::capture_import_options(
            model_text, mapping_text, keyframes_text, flight_text,
            frame_time != 0.0 ? std::optional<double>(frame_time) : std::nullopt);  // 0: the file's
        CaptureImport out;
        py::gil_scoped_release release;
        out.capture =
            std::make_shared<const saltus::CaptureFile>(saltus::import_capture_file(file, options));
        return out;
      },
      py::arg("path"), py::kw_only(), py::arg("model") = py::none(),
      py::arg("mapping") = py::none(), py::arg("keyframes") = py::none(),
      py::arg("flight") = py::none(), py::arg("frame_time") = 0.0,
      documented("import_capture(path, *, model=None, mapping=None, keyframes=None, flight=None, "
                 "frame_time=0.0)",
                 "`saltus import`: a BVH capture mapped onto the body model (default the "
                 "bundled zatsiorsky-66kg), its flight phase and take-off state found, keyframes "
                 "picked. mapping: a skeleton mapping file for names no convention knows; "
                 "keyframes: a count >= 2, 'all', or None (the fewest that meet every frame "
                 "within tolerance); flight: (start, end) in seconds of the clip instead of "
                 "finding it from the feet; frame_time: seconds per frame instead of the "
                 "file's (0). Returns a CaptureImport.")
          .c_str());

  std::string format_names;
  for (const saltus::ExportFormat& f : saltus::export_formats())
    format_names += (format_names.empty() ? "'" : ", '") + f.name + "' (" + f.title + ")";
  m.def(
      "export",
      [](py::handle source, py::handle out, const std::string& format, double fps,
         py::handle capture) {
        saltus::ExportOptions options;
        if (fps != 0.0) options.fps = fps;  // 0: the default rate
        if (!capture.is_none()) options.capture = path_argument(capture, "capture");
        const std::string target = path_argument(out, "out");
        saltus::ExportSummary summary;
        if (py::isinstance<PyMotion>(source)) {
          const saltus::MotionFile file = motion_file(*py::cast<MotionPtr>(source));
          py::gil_scoped_release release;
          summary = saltus::export_motion(file, format, target, options);
        } else {
          const std::string path = path_argument(source, "source");
          py::gil_scoped_release release;
          summary = saltus::export_source(path, format, target, options);
        }
        py::dict d;
        d["format"] = summary.format;
        d["motion"] = summary.motion;
        d["model"] = summary.model;
        d["frames"] = summary.frames;
        d["frame_time"] = summary.frame_time;
        d["description"] = summary.description;
        d["files"] = summary.files;
        d["bytes"] = summary.bytes;
        return d;
      },
      py::arg("source"), py::arg("out"), py::kw_only(), py::arg("format"), py::arg("fps") = 0.0,
      py::arg("capture") = py::none(),
      documented("export(source, out, *, format, fps=0.0, capture=None)",
                 "`saltus export`: `source` (a Motion in memory, or a motion file, a capture or "
                 "a result folder of optimize or import) written to `out` (a file, or a folder "
                 "for the folder formats) in `format`, one of the library's export formats: " +
                     format_names +
                     ". fps: frames per second of the sampled formats (0: the keyframes' rate "
                     "when even, else 60); capture: the motion capture the page draws beside "
                     "the athlete. Never over a file Saltus did not write. Returns a dict: "
                     "format, motion, model, frames, frame_time, description, files, bytes.")
          .c_str());
  m.def(
      "export_formats",
      []() {
        py::list out;
        for (const saltus::ExportFormat& f : saltus::export_formats()) {
          py::dict d;
          d["name"] = f.name;
          d["title"] = f.title;
          d["extension"] = f.extension;
          d["sampled"] = f.sampled;
          out.append(d);
        }
        return out;
      },
      documented("export_formats()",
                 "The formats export writes, from the library's table: name, title, the "
                 "output's extension ('' for a folder) and whether it is sampled at fps.")
          .c_str());

  // ---- athletes' models ----
  const saltus::StrengthSpec strength_defaults;
  const std::string strength_parameters =
      "age=" + saltus::format_number("%.1f", strength_defaults.age_years) + ", strength='" +
      strength_defaults.reference + "'";
  const std::string strength_docs =
      " age (years) and strength ('population': Anderson 2007's legs by sex and age, the upper "
      "body scaled alike; 'elite-gymnast') give the athlete's strength curves, as the CLI's "
      "--age and --strength.";
  m.def(
      "model_new",
      [](double height, double mass, const std::string& sex, const std::string& name, double age,
         const std::string& strength) {
        saltus::AthleteSize size;
        size.height_m = height;
        size.mass_kg = mass;
        size.sex = saltus::parse_sex(sex, "--sex");
        size.name = name;
        saltus::BodyModel model = saltus::new_athlete_model(size);
        model.strength = saltus::strength_from_flags(strength, sex, age);
        return new_model(model);
      },
      py::arg("height"), py::arg("mass"), py::arg("sex"), py::arg("name") = "",
      py::arg("age") = strength_defaults.age_years,
      py::arg("strength") = strength_defaults.reference,
      documented("model_new(height, mass, sex, name='', " + strength_parameters + ")",
                 "`saltus model new`: the body model of a person height m tall weighing mass kg, "
                 "sex 'female' or 'male' (de Leva 1996, on the bundled model's 13 segments); "
                 "named from them unless `name`." +
                     strength_docs + " Returns a Model (Model.write saves it).")
          .c_str());
  m.def(
      "model_scale",
      [](py::handle model, double height, double mass, const std::string& name) {
        const std::optional<saltus::BodyModel> source = model_argument(model);
        if (!source) throw_input_error("model", "a model is needed");
        return new_model(saltus::scaled_athlete_model(*source, height, mass, name));
      },
      py::arg("model"), py::arg("height"), py::arg("mass"), py::arg("name") = "",
      documented("model_scale(model, height, mass, name='')",
                 "`saltus model scale`: `model` (a Model, bundled name or file) scaled to a "
                 "person height m tall weighing mass kg: lengths by the standing height, masses "
                 "by the mass, inertias as mass × length². Returns a Model.")
          .c_str());
  m.def(
      "model_yeadon",
      [](py::handle measurements, const std::string& densities, double mass,
         const std::string& name, const std::string& sex, double age, const std::string& strength) {
        const std::string path = path_argument(measurements, "measurements");
        saltus::YeadonModel made = saltus::yeadon_athlete_model(path, densities, mass, name);
        made.model.strength = saltus::strength_from_flags(strength, sex, age);
        for (const std::string& warning : made.warnings)
          if (PyErr_WarnEx(PyExc_UserWarning, (path + ": " + warning).c_str(), 1) != 0)
            throw py::error_already_set();
        return new_model(made.model);
      },
      py::arg("measurements"), py::arg("densities") = "dempster", py::arg("mass") = 0.0,
      py::arg("name") = "", py::arg("sex") = "male", py::arg("age") = strength_defaults.age_years,
      py::arg("strength") = strength_defaults.reference,
      documented("model_yeadon(measurements, densities='dempster', mass=0.0, name='', "
                 "sex='male', " +
                     strength_parameters + ")",
                 "`saltus model yeadon`: Yeadon's 1990 geometric model of the person measured "
                 "in the file (95 measurements, the yeadon package's text format), densities "
                 "'dempster', 'chandler' or 'clauser', scaled to `mass` kg when > 0; sex (for "
                 "the strength tables)," +
                     strength_docs +
                     " Measurements that look wrong but are usable are UserWarnings. Returns a "
                     "Model.")
          .c_str());
  m.def(
      "model_info",
      [](py::handle model) {
        const std::optional<saltus::BodyModel> given = model_argument(model);
        if (!given) throw_input_error("model", "a model is needed");
        return python_json(saltus::model_summary_to_json(saltus::summarize_model(*given)));
      },
      py::arg("model"),
      documented("model_info(model)",
                 "`saltus model info --json`: the model's segments (mass kg and %, length, CoM, "
                 "principal inertias), total mass, standing height, whole-body CoM and inertia "
                 "standing (saltus-model-info/1), as a dict.")
          .c_str());

  // ---- result folders ----
  py::class_<ResultFolder>(m, "ResultFolder",
                           "A result folder of evaluate, simulate or optimize read back: "
                           "result.json and its trajectories as Flights (the arrays "
                           "trajectory.csv holds).")
      .def_property_readonly("path", [](const ResultFolder& r) { return r.folder->path; })
      .def_property_readonly(
          "result",
          [](const ResultFolder& r) {
            return python_json(saltus::result_to_json(r.folder->result));
          },
          "result.json, as a dict")
      .def_readonly("before", &ResultFolder::before,
                    "trajectory.csv (an optimisation's trajectory_before.csv), a Flight")
      .def_readonly("after", &ResultFolder::after,
                    "an optimisation's trajectory_after.csv, a Flight, or None");
  m.def(
      "read_result",
      [](py::handle dir) {
        const std::string path = path_argument(dir, "dir");
        std::shared_ptr<const saltus::ResultFolder> folder;
        std::shared_ptr<const saltus::BodyModel> model;
        {
          py::gil_scoped_release release;
          folder = std::make_shared<const saltus::ResultFolder>(saltus::read_result_folder(path));
          model = std::make_shared<const saltus::BodyModel>(
              saltus::load_body_model(saltus::output_file(path, "model.json", "a result folder")));
        }
        ResultFolder out;
        out.folder = folder;
        out.before = csv_flight(folder, model, folder->before);
        if (folder->after) out.after = csv_flight(folder, model, *folder->after);
        return out;
      },
      py::arg("dir"),
      documented("read_result(dir)",
                 "Reads a result folder of evaluate, simulate or optimize (the CLI's or "
                 "Evaluation.write's). Raises InputError naming the file and field that is "
                 "missing or malformed. Returns a ResultFolder.")
          .c_str());

  // ---- studies ----
  m.def(
      "study_athletes",
      [](py::handle motion, const std::vector<std::string>& models, py::handle out,
         const std::string& takeoff, py::object jobs, const std::string& shard, bool resume,
         double case_time_limit, py::object progress, py::kwargs kwargs) {
        const saltus::OptionValues values =
            option_values(kwargs, OptionUse::kOptimization, "study_athletes");
        const saltus::StudyJob job = saltus::athletes_study_job(
            path_argument(motion, "motion"), models, takeoff, values.optimize_options());
        return run_study_job(job, path_argument(out, "out"), jobs, shard, resume, case_time_limit,
                             progress);
      },
      py::arg("motion"), py::arg("models"), py::arg("out"), py::kw_only(),
      py::arg("takeoff") = "same-spin", py::arg("jobs") = py::none(), py::arg("shard") = "",
      py::arg("resume") = false, py::arg("case_time_limit") = saltus::kDefaultCaseTimeLimitS,
      py::arg("progress") = py::none(),
      documented("study_athletes(motion, models, out, *, takeoff='same-spin', jobs=None, "
                 "shard='', resume=False, case_time_limit=" +
                     saltus::format_number("%.1f", saltus::kDefaultCaseTimeLimitS) +
                     ", progress=None, " + option_parameters(OptionUse::kOptimization) + ")",
                 std::string("`saltus study athletes`: the motion file on its own model, then "
                             "on each of `models` (model files or bundled names), optimised as "
                             "optimize would, tabulated in OUT/athletes.md and athletes.csv. ") +
                     kRunDoc + "\n\nOptions: those of optimize.")
          .c_str());
  m.def(
      "study_mass",
      [](py::handle motion, py::handle out, const std::vector<std::string>& scale, double factor,
         const std::vector<std::string>& loads, bool paper_protocol, int samples, int max_iter) {
        saltus::check_flag("--factor", factor, "study mass");
        const saltus::MotionFile file = motion_file(*motion_argument(motion));
        saltus::MassStudyOptions options;
        options.optimize = study_options(samples, max_iter, false);
        options.paper_protocol = paper_protocol;
        options.scaled_segments = scale;
        options.factor = factor;
        options.load_segments = loads;
        const std::string dir = path_argument(out, "out");
        nlohmann::json written;
        {
          py::gil_scoped_release release;
          const saltus::MassStudyResult study = saltus::run_mass_study(file, options);
          written = saltus::write_mass_outputs(dir, file, study, options);
        }
        return python_json(written);
      },
      py::arg("motion"), py::arg("out"), py::kw_only(),
      py::arg("scale") = saltus::MassStudyOptions{}.scaled_segments,
      py::arg("factor") = saltus::MassStudyOptions{}.factor,
      py::arg("loads") = saltus::MassStudyOptions{}.load_segments,
      py::arg("paper_protocol") = false, py::arg("samples") = saltus::kDefaultSamples,
      py::arg("max_iter") = saltus::SolverOptions{}.max_iterations,
      documented("study_mass(motion, out, *, scale=" +
                     list_text(saltus::MassStudyOptions{}.scaled_segments) + ", factor=" +
                     saltus::format_number("%.10g", saltus::MassStudyOptions{}.factor) +
                     ", loads=" + list_text(saltus::MassStudyOptions{}.load_segments) +
                     ", paper_protocol=False, " + study_option_parameters() + ")",
                 "`saltus study mass`: the motion optimised with its model's masses and with "
                 "the `scale` segments' mass and inertia times `factor`; the `loads` segments' "
                 "joint loads over time in OUT/mass.csv, a summary in mass.md. Returns "
                 "result.json as a dict.")
          .c_str());
  m.def(
      "study_convergence",
      [](std::vector<py::object> motions, py::handle out, const std::vector<double>& epsilons,
         const std::vector<double>& mass_errors, const std::vector<std::string>& mass_segments,
         const std::vector<double>& timing_errors, unsigned seed, bool no_early_stop, int samples,
         int max_iter, py::object jobs, const std::string& shard, bool resume,
         double case_time_limit, py::object progress) {
        for (const auto& [flag, values] :
             {std::pair{"--epsilons", &epsilons}, std::pair{"--mass-errors", &mass_errors},
              std::pair{"--timing-errors", &timing_errors}})
          for (double value : *values)
            saltus::check_flag(flag, value, "study convergence");
        std::vector<saltus::LabelledMotion> labelled;
        for (const py::object& motion : motions) {
          const std::string path = path_argument(motion, "motions");
          labelled.push_back({saltus::motion_label(path), saltus::load_motion_or_capture(path)});
        }
        saltus::ConvergenceStudyOptions options;
        options.optimize = study_options(samples, max_iter, true);
        options.epsilons = epsilons;
        options.mass_errors.clear();
        for (double percent : mass_errors)
          options.mass_errors.push_back(percent / 100.0);
        options.mass_segments = mass_segments;
        options.timing_errors = timing_errors;
        options.seed = seed;
        if (no_early_stop) options.strict_checkpoints.clear();
        return run_study_job(saltus::convergence_study_job(labelled, options),
                             path_argument(out, "out"), jobs, shard, resume, case_time_limit,
                             progress);
      },
      py::arg("motions"), py::arg("out"), py::kw_only(),
      py::arg("epsilons") = saltus::ConvergenceStudyOptions{}.epsilons,
      py::arg("mass_errors") = default_mass_errors_percent(),
      py::arg("mass_segments") = saltus::ConvergenceStudyOptions{}.mass_segments,
      py::arg("timing_errors") = saltus::ConvergenceStudyOptions{}.timing_errors,
      py::arg("seed") = saltus::ConvergenceStudyOptions{}.seed, py::arg("no_early_stop") = false,
      py::arg("samples") = saltus::kDefaultSamples,
      py::arg("max_iter") = saltus::SolverOptions{}.max_iterations, py::arg("jobs") = py::none(),
      py::arg("shard") = "", py::arg("resume") = false,
      py::arg("case_time_limit") = saltus::kDefaultCaseTimeLimitS, py::arg("progress") = py::none(),
      documented(
          "study_convergence(motions, out, *, epsilons=" +
              list_text(saltus::ConvergenceStudyOptions{}.epsilons) +
              ", mass_errors=" + list_text(default_mass_errors_percent()) +
              ", mass_segments=" + list_text(saltus::ConvergenceStudyOptions{}.mass_segments) +
              ", timing_errors=" + list_text(saltus::ConvergenceStudyOptions{}.timing_errors) +
              ", seed=" + std::to_string(saltus::ConvergenceStudyOptions{}.seed) +
              ", no_early_stop=False, " + study_option_parameters() +
              ", jobs=None, shard='', resume=False, case_time_limit=" +
              saltus::format_number("%.1f", saltus::kDefaultCaseTimeLimitS) + ", progress=None)",
          std::string("`saltus study convergence`: the relaxed model against the strict "
                      "one (each ε, N or N·m) under mass errors (percent, on "
                      "mass_segments) and keyframe-time errors (s), at the paper's "
                      "resolution; OUT/convergence.csv and convergence.md. ") +
              kRunDoc)
          .c_str());
  m.def(
      "study_merge",
      [](std::vector<py::object> dirs, py::handle out) {
        std::vector<std::string> inputs;
        for (const py::object& d : dirs)
          inputs.push_back(path_argument(d, "dirs"));
        const std::string target = path_argument(out, "out");
        nlohmann::json merged;
        {
          py::gil_scoped_release release;
          merged = saltus::merge_study_folders(inputs, target);
        }
        return python_json(merged);
      },
      py::arg("dirs"), py::arg("out"),
      documented("study_merge(dirs, out)",
                 "`saltus study merge`: the shard folders of one study combined into exactly "
                 "the folder one run writes. Returns its result.json.")
          .c_str());
  m.def(
      "paper",
      [](py::handle motions_dir, py::handle out, bool quick, bool no_early_stop, int samples,
         int max_iter, py::object jobs, const std::string& shard, bool resume,
         double case_time_limit, py::object progress) {
        saltus::PaperReportOptions options;
        options.motions_dir = path_argument(motions_dir, "motions_dir");
        options.quick = quick;
        options.optimize = study_options(samples, max_iter, true);
        if (no_early_stop) options.strict_checkpoints.clear();
        return run_study_job(saltus::paper_report_job(options), path_argument(out, "out"), jobs,
                             shard, resume, case_time_limit, progress);
      },
      py::arg("motions_dir"), py::arg("out"), py::kw_only(), py::arg("quick") = false,
      py::arg("no_early_stop") = false, py::arg("samples") = saltus::kDefaultSamples,
      py::arg("max_iter") = saltus::SolverOptions{}.max_iterations, py::arg("jobs") = py::none(),
      py::arg("shard") = "", py::arg("resume") = false,
      py::arg("case_time_limit") = saltus::kDefaultCaseTimeLimitS, py::arg("progress") = py::none(),
      documented(
          "paper(motions_dir, out, *, quick=False, no_early_stop=False, " +
              study_option_parameters() + ", jobs=None, shard='', resume=False, case_time_limit=" +
              saltus::format_number("%.1f", saltus::kDefaultCaseTimeLimitS) + ", progress=None)",
          std::string("`saltus paper`: the paper's experiments on M1-M7 and the dive "
                      "(Table 1, the mass and convergence studies) in OUT/report.md. ") +
              kRunDoc)
          .c_str());
}

}  // namespace saltus_python
