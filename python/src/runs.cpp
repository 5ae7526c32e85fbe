#include <pybind11/stl.h>

#include <atomic>
#include <exception>

#include "module.h"
#include "saltus/evaluation/evaluate.h"
#include "saltus/evaluation/simulate.h"
#include "saltus/formats/result_json.h"
#include "saltus/optim/optimize.h"
#include "saltus/use_cases/athlete_models.h"
#include "saltus/use_cases/result_folders.h"

namespace saltus_python {

namespace {

using saltus::OptionUse;

/// saltus.Evaluation: a motion's samples through inverse dynamics and its figures (the dense
/// check), with the motion and the options of the run.
struct Evaluation : Flight {
  std::shared_ptr<const saltus::MotionFile> file;
  std::shared_ptr<const saltus::MotionEvaluation> evaluation;
  saltus::EvaluateOptions options;
  py::object result_cache;
};

struct Simulation : Flight {
  std::shared_ptr<const saltus::MotionFile> file;
  std::shared_ptr<const saltus::SimulationResult> simulation;
  saltus::EvaluateOptions options;
  py::object result_cache;
};

struct Optimization {
  std::shared_ptr<const saltus::MotionFile> file;
  std::shared_ptr<const saltus::OptimizationResult> result;
  saltus::OptimizeOptions options;
  std::shared_ptr<Evaluation> before, after;
  py::object result_cache;
};

struct Progress {
  saltus::ProgressInfo info;
};

std::shared_ptr<Evaluation> new_evaluation(std::shared_ptr<const saltus::MotionFile> file,
                                           std::shared_ptr<const saltus::MotionEvaluation> e,
                                           const saltus::EvaluateOptions& options) {
  auto out = std::make_shared<Evaluation>();
  out->samples = std::shared_ptr<const std::vector<saltus::SampleRecord>>(e, &e->samples);
  out->model = std::shared_ptr<const saltus::BodyModel>(file, &file->model);
  out->file = std::move(file);
  out->evaluation = std::move(e);
  out->options = options;
  return out;
}

/// The motion of a run: the motion argument, flown by `model` when one is given (the CLI's
/// --model).
saltus::MotionFile run_motion(py::handle motion, py::handle model) {
  saltus::MotionFile file = motion_file(*motion_argument(motion));
  if (const std::optional<saltus::BodyModel> other = model_argument(model)) {
    file = with_model(std::move(file), *other);
    if (py::isinstance<py::str>(model)) file.motion.model = py::cast<std::string>(model);
  }
  return file;
}

py::object figures(const saltus::ForceMetrics& m) {
  return python_json(saltus::force_metrics_to_json(m));
}

const char* const kFiguresDoc =
    "the root force figures of the dense check, a dict as result.json's \"before\": "
    "avg_root_force = sqrt(J/6) N (the paper's 'average force acting on the root'), objective "
    "J = (1/T)∫ΣF_i² dt N², rms_force_N and max_force_N, rms_moment_Nm and max_moment_Nm";

/// Runs the optimiser with the GIL released. Each iteration takes the GIL briefly: it calls
/// `progress` (if any), and in the main thread lets Python see Ctrl+C. Ctrl+C, or the callback
/// raising StopIteration, cancels the solve (the library returns its best iterate, status
/// "cancelled", as the app's Cancel does); any other exception from the callback cancels it too
/// and is raised when the library has returned.
saltus::OptimizationResult run_optimizer(const saltus::MotionFile& file,
                                         const saltus::OptimizeOptions& options,
                                         const py::object& progress) {
  std::atomic<bool> cancel{false};
  std::exception_ptr raised;
  const saltus::ProgressCallback on_iteration = [&](const saltus::ProgressInfo& info) {
    py::gil_scoped_acquire gil;
    if (cancel.load() || raised) return;
    try {
      if (!progress.is_none()) progress(Progress{info});
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    } catch (py::error_already_set& e) {
      if (e.matches(PyExc_KeyboardInterrupt) || e.matches(PyExc_StopIteration)) {
        cancel = true;
        return;
      }
      raised = std::current_exception();
      cancel = true;
    }
  };
  saltus::OptimizationResult result;
  {
    py::gil_scoped_release release;
    result = saltus::optimize_motion(file.motion, file.model, options, on_iteration, &cancel);
  }
  if (raised) std::rethrow_exception(raised);
  return result;
}

std::string evaluation_repr(const Evaluation& e, const char* kind) {
  return std::string("<saltus.") + kind + " of " + e.file->motion.name + " on " +
         e.file->model.name + ": " + std::to_string(e.samples->size()) + " samples" +
         saltus::format_number(", average root force %.4g N>",
                               e.evaluation->metrics.avg_root_force);
}

}  // namespace

void bind_runs(py::module_& m) {
  py::class_<Progress>(m, "Progress",
                       "One iteration of the optimiser, as the progress callback "
                       "of optimize receives it.")
      .def_property_readonly("iteration", [](const Progress& p) { return p.info.iteration; })
      .def_property_readonly(
          "objective", [](const Progress& p) { return p.info.objective; },
          "the objective of the NLP being solved")
      .def_property_readonly(
          "constraint_violation", [](const Progress& p) { return p.info.constraint_violation; },
          "Ipopt's inf_pr")
      .def_property_readonly(
          "elapsed_seconds", [](const Progress& p) { return p.info.elapsed_seconds; }, "s")
      .def("__repr__", [](const Progress& p) {
        return "<saltus.Progress iteration " + std::to_string(p.info.iteration) +
               saltus::format_number(", objective %.6e", p.info.objective) +
               saltus::format_number(", violation %.2e>", p.info.constraint_violation);
      });

  py::class_<Evaluation, Flight, std::shared_ptr<Evaluation>>(
      m, "Evaluation",
      "A motion interpolated (or as stored) and its dynamics: the samples (Flight's arrays) and "
      "the figures of the dense check, what `saltus evaluate` writes.")
      .def_property_readonly(
          "average_root_force",
          [](const Evaluation& e) { return e.evaluation->metrics.avg_root_force; },
          "sqrt(J/6), N: the paper's 'average force acting on the root' "
          "(dense check)")
      .def_property_readonly(
          "figures", [](const Evaluation& e) { return figures(e.evaluation->metrics); },
          kFiguresDoc)
      .def_property_readonly(
          "keyframe_times",
          [](const Evaluation& e) { return doubles_array(e.evaluation->keyframe_times); },
          "s, shape (keyframes,)")
      .def_property_readonly(
          "keyframe_errors",
          [](const Evaluation& e) {
            const saltus::KeyframeErrors& k = e.evaluation->keyframe_errors;
            py::dict d;
            d["max_translation_error_m"] = k.max_translation_error_m;
            d["max_quaternion_error"] = k.max_quaternion_error;
            d["max_rotation_error_deg"] = k.max_rotation_error_deg;
            return d;
          },
          "how far the trajectory passes from the keyframes: root translation m, quaternion "
          "distance, rotation degrees (maxima)")
      .def_property_readonly(
          "check_points", [](const Evaluation& e) { return e.evaluation->check.points; },
          "points of the dense check behind the figures")
      .def_property_readonly(
          "motion", [](const Evaluation& e) { return new_motion(*e.file); },
          "the motion evaluated (a copy)")
      .def_property_readonly(
          "result",
          [](Evaluation& e) {
            if (!e.result_cache)
              e.result_cache =
                  python_json(saltus::evaluation_result_json(*e.file, *e.evaluation, e.options));
            return e.result_cache;
          },
          "result.json of `saltus evaluate` for this run, as a dict (docs/formats.md)")
      .def(
          "write",
          [](const Evaluation& e, py::handle out) {
            const std::string dir = path_argument(out, "out");
            return write_released([&] {
              return saltus::write_evaluation_outputs(dir, *e.file, *e.evaluation, e.options);
            });
          },
          py::arg("out"),
          documented("write($self, out)",
                     "Writes the result folder of `saltus evaluate` (result.json, trajectory.csv, "
                     "model.json) atomically; returns result.json as a dict. Replaces only a "
                     "folder Saltus "
                     "wrote.")
              .c_str())
      .def("__repr__", [](const Evaluation& e) { return evaluation_repr(e, "Evaluation"); });

  py::class_<Simulation, Flight, std::shared_ptr<Simulation>>(
      m, "Simulation",
      "A free flight: the joints follow the motion, the body's orientation and position follow "
      "Newton's laws from the take-off state; what `saltus simulate` writes.")
      .def_property_readonly(
          "takeoff_angular_momentum",
          [](const Simulation& s) { return vector3_array(s.simulation->angular_momentum); },
          "the take-off L flown, about the CoM, world, kg·m²/s, shape (3,)")
      .def_property_readonly(
          "angular_momentum_from_file",
          [](const Simulation& s) { return s.simulation->angular_momentum_from_file; },
          "True: the motion's own take-off L; False: the constant nearest "
          "its L(t)")
      .def_property_readonly(
          "angular_momentum_spread",
          [](const Simulation& s) { return s.simulation->angular_momentum_spread; },
          "RMS of the motion's own L(t) about that constant, kg·m²/s")
      .def_property_readonly(
          "landing_root_error_deg",
          [](const Simulation& s) { return s.simulation->landing_root_error_deg; },
          "whole-body orientation at landing against the last keyframe, °")
      .def_property_readonly(
          "landing_com_error_m",
          [](const Simulation& s) { return s.simulation->landing_com_error_m; },
          "CoM at landing against the ballistic parabola, m")
      .def_property_readonly(
          "landing_vs_motion_deg",
          [](const Simulation& s) { return s.simulation->landing_vs_motion_deg; },
          "whole-body orientation at landing against the motion's own, °")
      .def_property_readonly(
          "landing_joint_error_deg",
          [](const Simulation& s) { return s.simulation->landing_joint_error_deg; },
          "per joint, the angle between the flown and the keyframed rotation at landing, °")
      .def_property_readonly(
          "figures", [](const Simulation& s) { return figures(s.simulation->metrics); },
          "the flight's root force figures (≈ 0 up to integration error); "
          "keys as Evaluation.figures")
      .def_property_readonly(
          "motion", [](const Simulation& s) { return new_motion(*s.file); },
          "the motion flown (a copy; on another athlete, its take-off "
          "adapted)")
      .def_property_readonly(
          "result",
          [](Simulation& s) {
            if (!s.result_cache)
              s.result_cache =
                  python_json(saltus::simulation_result_json(*s.file, *s.simulation, s.options));
            return s.result_cache;
          },
          "result.json of `saltus simulate` for this run, as a dict")
      .def(
          "write",
          [](const Simulation& s, py::handle out) {
            const std::string dir = path_argument(out, "out");
            return write_released([&] {
              return saltus::write_simulation_outputs(dir, *s.file, *s.simulation, s.options);
            });
          },
          py::arg("out"),
          documented(
              "write($self, out)",
              "Writes the result folder of `saltus simulate` atomically; returns result.json.")
              .c_str())
      .def("__repr__", [](const Simulation& s) {
        return "<saltus.Simulation of " + s.file->motion.name + " on " + s.file->model.name +
               saltus::format_number(": lands %.3g deg from the last keyframe>",
                                     s.simulation->landing_root_error_deg);
      });

  py::class_<Optimization, std::shared_ptr<Optimization>>(
      m, "Optimization",
      "An optimised motion and the run that made it: `before` (the interpolated input) and "
      "`after` (the optimised motion) evaluated on the same grid, the solver's report, and "
      "`motion`, the optimised motion (Motion.write saves it); what `saltus optimize` writes.")
      .def_readonly("before", &Optimization::before, "the interpolated input, an Evaluation")
      .def_readonly("after", &Optimization::after, "the optimised motion, an Evaluation")
      .def_property_readonly(
          "motion",
          [](const Optimization& o) {
            saltus::MotionFile f = *o.file;
            f.path.clear();
            f.motion = o.result->optimized_motion;
            return new_motion(f);
          },
          "the optimised motion (its spline stored, its keyframe times the optimised ones)")
      .def_property_readonly(
          "status", [](const Optimization& o) { return o.result->solve.status; },
          "'solved', or why not: 'max_iterations', 'cancelled', ...")
      .def_property_readonly("solved", [](const Optimization& o) { return o.result->solve.solved; })
      .def_property_readonly(
          "cancelled", [](const Optimization& o) { return o.result->solve.status == "cancelled"; },
          "stopped by Ctrl+C or the progress callback (StopIteration): the "
          "best iterate was kept")
      .def_property_readonly("iterations",
                             [](const Optimization& o) { return o.result->solve.iterations; })
      .def_property_readonly(
          "solve_seconds", [](const Optimization& o) { return o.result->solve.seconds; }, "s")
      .def_property_readonly(
          "keyframe_time_spreads",
          [](const Optimization& o) { return doubles_array(o.result->keyframe_time_spreads); },
          "per keyframe, how far its optimised time could move (s) before the residual rises "
          "by 0.1 N, shape (keyframes,)")
      .def_property_readonly("knots_per_interval",
                             [](const Optimization& o) { return o.result->knots_per_interval; })
      .def_property_readonly(
          "subdivisions", [](const Optimization& o) { return o.result->subdivisions; },
          "knot spans per keyframe interval of the optimised motion")
      .def_property_readonly(
          "result",
          [](Optimization& o) {
            if (!o.result_cache)
              o.result_cache =
                  python_json(saltus::optimization_result_json(*o.file, *o.result, o.options));
            return o.result_cache;
          },
          "result.json of `saltus optimize` for this run, as a dict")
      .def(
          "write",
          [](const Optimization& o, py::handle out) {
            const std::string dir = path_argument(out, "out");
            return write_released([&] {
              return saltus::write_optimization_outputs(dir, *o.file, *o.result, o.options);
            });
          },
          py::arg("out"),
          documented(
              "write($self, out)",
              "Writes the result folder of `saltus optimize` (result.json, trajectory_before.csv, "
              "trajectory_after.csv, model.json, optimized.motion.json) atomically; returns "
              "result.json.")
              .c_str())
      .def("__repr__", [](const Optimization& o) {
        return "<saltus.Optimization of " + o.file->motion.name + ": " + o.result->solve.status +
               saltus::format_number(", average root force %.4g N",
                                     o.result->before.metrics.avg_root_force) +
               saltus::format_number(" -> %.4g N>", o.result->after.metrics.avg_root_force);
      });

  const std::string evaluation_options = option_parameters(OptionUse::kEvaluation);
  const std::string evaluation_docs = option_docs(OptionUse::kEvaluation);

  m.def(
      "evaluate",
      [](py::handle motion, py::handle model, py::kwargs kwargs) {
        const saltus::OptionValues values =
            option_values(kwargs, OptionUse::kEvaluation, "evaluate");
        auto file = std::make_shared<const saltus::MotionFile>(run_motion(motion, model));
        const saltus::EvaluateOptions options = values.evaluate_options();
        std::shared_ptr<const saltus::MotionEvaluation> e;
        {
          py::gil_scoped_release release;
          e = std::make_shared<const saltus::MotionEvaluation>(
              saltus::evaluate_motion(file->motion, file->model, options));
        }
        return new_evaluation(file, e, options);
      },
      py::arg("motion"), py::arg("model") = py::none(),
      documented("evaluate(motion, model=None, *, " + evaluation_options + ")",
                 "Interpolates the keyframes (paper §5) and computes the root force and moment "
                 "the motion needs by inverse dynamics: `saltus evaluate`. `motion`: a Motion or "
                 "a path (a motion file or a .bvh capture); `model`: another athlete's Model, "
                 "bundled name or model file (the CLI's --model). Returns an Evaluation.\n\n"
                 "Options (the CLI's flags, checked by the same table):\n" +
                     evaluation_docs)
          .c_str());

  m.def(
      "simulate",
      [](py::handle motion, py::handle model, const std::string& takeoff, py::kwargs kwargs) {
        const saltus::OptionValues values =
            option_values(kwargs, OptionUse::kEvaluation, "simulate");
        const saltus::TakeoffRule rule = saltus::parse_takeoff_rule(takeoff, "takeoff");
        saltus::MotionFile own = motion_file(*motion_argument(motion));
        saltus::MotionFile flown = own;
        if (const std::optional<saltus::BodyModel> other = model_argument(model)) {
          saltus::MotionFile athlete = with_model(own, *other);
          if (py::isinstance<py::str>(model)) athlete.motion.model = py::cast<std::string>(model);
          py::gil_scoped_release release;
          flown = saltus::adapt_takeoff_to_athlete(own, std::move(athlete), rule);
        }
        auto file = std::make_shared<const saltus::MotionFile>(std::move(flown));
        const saltus::EvaluateOptions options = values.evaluate_options();
        std::shared_ptr<const saltus::SimulationResult> s;
        {
          py::gil_scoped_release release;
          s = std::make_shared<const saltus::SimulationResult>(
              saltus::simulate_motion(file->motion, file->model, options));
        }
        auto out = std::make_shared<Simulation>();
        out->samples = std::shared_ptr<const std::vector<saltus::SampleRecord>>(s, &s->samples);
        out->model = std::shared_ptr<const saltus::BodyModel>(file, &file->model);
        out->file = file;
        out->simulation = s;
        out->options = options;
        return out;
      },
      py::arg("motion"), py::arg("model") = py::none(), py::kw_only(),
      py::arg("takeoff") = "same-spin",
      documented("simulate(motion, model=None, *, takeoff='same-spin', " + evaluation_options + ")",
                 "Free flight: the joints follow the motion, the body's orientation and position "
                 "follow Newton's laws from the take-off state (`saltus simulate`). With `model`, "
                 "another athlete flies the same skill, the take-off carried over by `takeoff`: "
                 "'same-spin' (the same whole-body spin, L follows the athlete's inertia) or "
                 "'keep-momentum' (the same L). Returns a Simulation.\n\nOptions:\n" +
                     evaluation_docs)
          .c_str());

  m.def(
      "optimize",
      [](py::handle motion, py::handle model, py::object progress, py::kwargs kwargs) {
        const saltus::OptionValues values =
            option_values(kwargs, OptionUse::kOptimization, "optimize");
        if (!progress.is_none() && !PyCallable_Check(progress.ptr()))
          throw_input_error("progress", "expected a callable or None");
        auto file = std::make_shared<const saltus::MotionFile>(run_motion(motion, model));
        auto out = std::make_shared<Optimization>();
        out->options = values.optimize_options();
        auto result = std::make_shared<const saltus::OptimizationResult>(
            run_optimizer(*file, out->options, progress));
        const saltus::EvaluateOptions evaluated = values.evaluate_options();
        out->before = new_evaluation(
            file, std::shared_ptr<const saltus::MotionEvaluation>(result, &result->before),
            evaluated);
        saltus::MotionFile optimised = *file;
        optimised.motion = result->optimized_motion;
        out->after = new_evaluation(
            std::make_shared<const saltus::MotionFile>(std::move(optimised)),
            std::shared_ptr<const saltus::MotionEvaluation>(result, &result->after), evaluated);
        out->file = file;
        out->result = result;
        return out;
      },
      py::arg("motion"), py::arg("model") = py::none(), py::kw_only(),
      py::arg("progress") = py::none(),
      documented("optimize(motion, model=None, *, progress=None, " +
                     option_parameters(OptionUse::kOptimization) + ")",
                 "Optimises the motion so that it obeys Newton's laws as nearly as possible with "
                 "the keyframes within tolerance, keyframe times included (`saltus optimize`). "
                 "`progress(p)` is called after every iteration with a Progress; raising "
                 "StopIteration in it, or Ctrl+C, stops the solve after the current iteration "
                 "and returns the best iterate (status 'cancelled'). The GIL is released while "
                 "the library computes, so optimisations in several threads run at once. Returns "
                 "an Optimization.\n\nOptions (every option of the CLI's, the same names in "
                 "snake case, defaults and checks):\n" +
                     option_docs(OptionUse::kOptimization))
          .c_str());
}

}  // namespace saltus_python
