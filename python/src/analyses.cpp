#include <pybind11/stl.h>

#include "module.h"
#include "saltus/evaluation/twist_sources.h"
#include "saltus/evaluation/what_if.h"
#include "saltus/formats/result_json.h"
#include "saltus/formats/twist_files.h"
#include "saltus/formats/what_if_files.h"
#include "saltus/use_cases/athlete_models.h"
#include "saltus/use_cases/result_folders.h"

namespace saltus_python {

namespace {

using saltus::OptionUse;

struct TwistAnalysis {
  std::shared_ptr<const saltus::MotionFile> file;
  std::shared_ptr<const saltus::TwistSources> sources;
};

/// A motion prepared for what-if flights (the library's WhatIf): each fly() is one free flight.
struct WhatIf {
  std::shared_ptr<const saltus::MotionFile> file;
  std::shared_ptr<const saltus::WhatIf> prepared;
};

struct WhatIfFlight : Flight {
  std::shared_ptr<const saltus::MotionFile> file;
  std::shared_ptr<const saltus::WhatIf> prepared;
  std::shared_ptr<const saltus::WhatIfResult> result;
};

/// The motion of an analysis: on `model` when given, its take-off carried over by `takeoff`
/// (the CLI's --model and --takeoff).
saltus::MotionFile athlete_motion(py::handle motion, py::handle model, const std::string& takeoff) {
  const saltus::TakeoffRule rule = saltus::parse_takeoff_rule(takeoff, "takeoff");
  const saltus::MotionFile own = motion_file(*motion_argument(motion));
  const std::optional<saltus::BodyModel> other = model_argument(model);
  if (!other) return own;
  saltus::MotionFile athlete = with_model(own, *other);
  if (py::isinstance<py::str>(model)) athlete.motion.model = py::cast<std::string>(model);
  py::gil_scoped_release release;
  return saltus::adapt_takeoff_to_athlete(own, std::move(athlete), rule);
}

/// The tuck as result.json records it, with the bend over time the rule read as arrays.
py::object tuck_dict(const saltus::TuckPhases& t) {
  py::object d = python_json(saltus::tuck_json(t));
  d["times"] = readonly(doubles_array(t.times));
  d["bend_deg"] = readonly(doubles_array(t.bend_deg));
  return d;
}

py::object yeadon_dict(const saltus::YeadonSummary& y) {
  return python_json(saltus::rotation_json(y));
}

const char* const kTuckDoc =
    "the tuck as the library reads it off the legs' bend, a dict as result.json's \"tuck\": "
    "found (and reason when not), bend at take-off, peak and landing (°), the tuck-in's start "
    "and end and the opening's (s), the ranges tuck_later and open_later may take (s); and the "
    "bend over time (times s, bend_deg °, numpy arrays)";

}  // namespace

void bind_analyses(py::module_& m) {
  py::class_<TwistAnalysis, std::shared_ptr<TwistAnalysis>>(
      m, "TwistAnalysis",
      "Where a twist comes from (`saltus analyse twist`): the tilt at mid-flight of the motion's "
      "free flight split into the take-off's share and each aerial movement's (Yeadon's "
      "counterfactual flights; the shares add up).")
      .def_property_readonly("sentence", [](const TwistAnalysis& t) { return t.sources->sentence; })
      .def_property_readonly(
          "shares",
          [](const TwistAnalysis& t) {
            py::list out;
            for (const saltus::TwistShare& s : t.sources->shares) {
              py::dict d;
              d["source"] = s.source;
              d["tilt_deg"] = s.tilt_deg;
              d["percent"] = s.percent;
              out.append(d);
            }
            return out;
          },
          "the take-off first, then each aerial movement: source, tilt_deg (its share of the "
          "tilt at mid-flight, °) and percent of the total (< 0 works against it)")
      .def_property_readonly(
          "total_tilt_deg", [](const TwistAnalysis& t) { return t.sources->total_tilt_deg; },
          "tilt of the free flight at mid-flight, °")
      .def_property_readonly(
          "twists", [](const TwistAnalysis& t) { return t.sources->twists; },
          "Yeadon's twists of the free flight, revolutions")
      .def_property_readonly(
          "reference_time", [](const TwistAnalysis& t) { return t.sources->reference_time_s; },
          "mid-flight, s")
      .def_property_readonly(
          "times", [](const TwistAnalysis& t) { return readonly(doubles_array(t.sources->times)); },
          "s, shape (m,)")
      .def_property_readonly(
          "tilt_deg",
          [](const TwistAnalysis& t) {
            py::dict out;
            for (std::size_t i = 0; i < t.sources->flight_names.size(); ++i)
              out[py::str(t.sources->flight_names[i])] =
                  readonly(doubles_array(t.sources->tilt_deg[i]));
            return out;
          },
          "tilt over time (°, shape (m,)) of the actual flight and of the counterfactuals, by "
          "flight name")
      .def_property_readonly(
          "result",
          [](const TwistAnalysis& t) {
            return python_json(saltus::twist_result_json(*t.file, *t.sources));
          },
          "result.json of `saltus analyse twist`, as a dict")
      .def(
          "write",
          [](const TwistAnalysis& t, py::handle out) {
            const std::string dir = path_argument(out, "out");
            return write_released(
                [&] { return saltus::write_twist_outputs(dir, *t.file, *t.sources); });
          },
          py::arg("out"),
          documented("write($self, out)", "Writes result.json, twist.csv and twist.md atomically.")
              .c_str())
      .def("__repr__", [](const TwistAnalysis& t) {
        return "<saltus.TwistAnalysis: " + t.sources->sentence + ">";
      });

  py::class_<WhatIfFlight, Flight, std::shared_ptr<WhatIfFlight>>(
      m, "WhatIfFlight",
      "One what-if flight (`saltus analyse what-if`): the same take-off, the tuck moved or "
      "tightened, flown again; its samples (Flight's arrays) and how it lands.")
      .def_property_readonly("sentence", [](const WhatIfFlight& w) { return w.result->sentence; })
      .def_property_readonly("verdict", [](const WhatIfFlight& w) { return w.result->verdict; })
      .def_property_readonly("change", [](const WhatIfFlight& w) { return w.result->change_words; })
      .def_property_readonly(
          "landing", [](const WhatIfFlight& w) { return yeadon_dict(w.result->landing); },
          "Yeadon's counts of the flight: somersaults, twists (revolutions), "
          "max_tilt_deg, description")
      .def_property_readonly(
          "somersault_over_deg",
          [](const WhatIfFlight& w) { return w.result->somersault_over_deg; },
          "landing against the motion as keyframed, ° (> 0 over, < 0 short)")
      .def_property_readonly(
          "twist_over_deg", [](const WhatIfFlight& w) { return w.result->twist_over_deg; }, "°")
      .def_property_readonly("within_tolerance",
                             [](const WhatIfFlight& w) { return w.result->within_tolerance; })
      .def_property_readonly(
          "tuck", [](const WhatIfFlight& w) { return tuck_dict(w.result->tuck); }, kTuckDoc)
      .def_property_readonly(
          "result",
          [](const WhatIfFlight& w) {
            return python_json(saltus::what_if_result_json(*w.file, *w.prepared, *w.result));
          },
          "result.json of `saltus analyse what-if`, as a dict")
      .def(
          "write",
          [](const WhatIfFlight& w, py::handle out) {
            const std::string dir = path_argument(out, "out");
            return write_released([&] {
              return saltus::write_what_if_outputs(dir, *w.file, *w.prepared, *w.result);
            });
          },
          py::arg("out"),
          documented("write($self, out)",
                     "Writes result.json, what_if.csv, trajectory.csv and model.json atomically.")
              .c_str())
      .def("__repr__", [](const WhatIfFlight& w) {
        return "<saltus.WhatIfFlight: " + w.result->sentence + ">";
      });

  const auto fly = [](const WhatIf& w, double tuck_later, double open_later, double tuck_scale) {
    saltus::WhatIfChange change;
    change.tuck_later_s = tuck_later;
    change.open_later_s = open_later;
    change.tuck_scale = tuck_scale;
    std::shared_ptr<const saltus::WhatIfResult> result;
    {
      py::gil_scoped_release release;
      result = std::make_shared<const saltus::WhatIfResult>(w.prepared->fly(change));
    }
    auto out = std::make_shared<WhatIfFlight>();
    out->samples =
        std::shared_ptr<const std::vector<saltus::SampleRecord>>(result, &result->flight.samples);
    out->model = std::shared_ptr<const saltus::BodyModel>(w.file, &w.file->model);
    out->file = w.file;
    out->prepared = w.prepared;
    out->result = result;
    return out;
  };
  const auto prepare = [](py::handle motion, py::handle model, const std::string& takeoff,
                          const py::kwargs& kwargs) {
    const saltus::OptionValues values = option_values(kwargs, OptionUse::kEvaluation, "what_if");
    WhatIf w;
    w.file = std::make_shared<const saltus::MotionFile>(athlete_motion(motion, model, takeoff));
    const saltus::EvaluateOptions options = values.evaluate_options();
    py::gil_scoped_release release;
    w.prepared = std::make_shared<const saltus::WhatIf>(w.file->motion, w.file->model, options);
    return w;
  };
  const std::string evaluation_options = option_parameters(OptionUse::kEvaluation);
  const std::string evaluation_docs = option_docs(OptionUse::kEvaluation);
  const std::string change_docs =
      "tuck_later: the tuck-in this much later, s (< 0: earlier; WhatIf.tuck gives the range); "
      "open_later: the opening this much later, s; tuck_scale: the hips' and knees' turn from "
      "their take-off pose times this, 0.8-1.2 (> 1: tighter). ";

  py::class_<WhatIf>(m, "WhatIf",
                     "A motion prepared for what-if flights (the app's What if panel): its "
                     "take-off, tuck and unchanged flight worked out once; fly() flies one change.")
      .def(py::init(prepare), py::arg("motion"), py::arg("model") = py::none(), py::kw_only(),
           py::arg("takeoff") = "same-spin",
           documented("__init__($self, motion, model=None, *, takeoff='same-spin', " +
                          evaluation_options + ")",
                      "Prepares the motion (on `model`'s athlete when given, the take-off "
                      "carried over by `takeoff`). Options:\n" +
                          evaluation_docs)
               .c_str())
      .def("fly", fly, py::kw_only(), py::arg("tuck_later") = 0.0, py::arg("open_later") = 0.0,
           py::arg("tuck_scale") = 1.0,
           documented("fly($self, *, tuck_later=0.0, open_later=0.0, tuck_scale=1.0)",
                      "The same take-off with this change, flown: a WhatIfFlight. " + change_docs +
                          "A change the motion does not allow raises InputError.")
               .c_str())
      .def_property_readonly(
          "tuck", [](const WhatIf& w) { return tuck_dict(w.prepared->tuck()); }, kTuckDoc)
      .def_property_readonly(
          "target", [](const WhatIf& w) { return yeadon_dict(w.prepared->target()); },
          "the landing the motion is keyframed to (Yeadon's counts)")
      .def_property_readonly(
          "unchanged_landing",
          [](const WhatIf& w) { return yeadon_dict(w.prepared->unchanged_landing()); },
          "how the motion's own free flight lands (Yeadon's counts)")
      .def_property_readonly(
          "takeoff_angular_momentum",
          [](const WhatIf& w) { return vector3_array(w.prepared->angular_momentum()); },
          "kg·m²/s, world, shape (3,)");

  m.def(
      "what_if",
      [prepare, fly](py::handle motion, py::handle model, const std::string& takeoff,
                     double tuck_later, double open_later, double tuck_scale, py::kwargs kwargs) {
        return fly(prepare(motion, model, takeoff, kwargs), tuck_later, open_later, tuck_scale);
      },
      py::arg("motion"), py::arg("model") = py::none(), py::kw_only(),
      py::arg("takeoff") = "same-spin", py::arg("tuck_later") = 0.0, py::arg("open_later") = 0.0,
      py::arg("tuck_scale") = 1.0,
      documented("what_if(motion, model=None, *, takeoff='same-spin', tuck_later=0.0, "
                 "open_later=0.0, tuck_scale=1.0, " +
                     evaluation_options + ")",
                 "`saltus analyse what-if`: the same take-off with the tuck moved earlier or "
                 "later, the opening moved, or the tuck tighter or looser, flown again; "
                 "WhatIf(motion, ...).fly(...). " +
                     change_docs + "Returns a WhatIfFlight.\n\nOptions:\n" + evaluation_docs)
          .c_str());

  m.def(
      "analyse_twist",
      [](py::handle motion, py::handle model, const std::string& takeoff, py::kwargs kwargs) {
        const saltus::OptionValues values =
            option_values(kwargs, OptionUse::kEvaluation, "analyse_twist");
        auto out = std::make_shared<TwistAnalysis>();
        out->file =
            std::make_shared<const saltus::MotionFile>(athlete_motion(motion, model, takeoff));
        const saltus::EvaluateOptions options = values.evaluate_options();
        py::gil_scoped_release release;
        out->sources = std::make_shared<const saltus::TwistSources>(
            saltus::twist_sources(out->file->motion, out->file->model, options));
        return out;
      },
      py::arg("motion"), py::arg("model") = py::none(), py::kw_only(),
      py::arg("takeoff") = "same-spin",
      documented(
          "analyse_twist(motion, model=None, *, takeoff='same-spin', " + evaluation_options + ")",
          "`saltus analyse twist`: where the twist comes from, the tilt at mid-flight "
          "split into the take-off's share and each arm's, the legs' and the trunk's. "
          "Returns a TwistAnalysis.\n\nOptions:\n" +
              evaluation_docs)
          .c_str());
}

}  // namespace saltus_python
