#pragma once
/// @file
/// What the module's files share: the Python objects that hold a model, a motion and a run's
/// samples, the conversions between numpy arrays and the library's vectors, and the option
/// table as keyword arguments. The module only translates: every computation, file and check is
/// a library call (python/README.md).

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <functional>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "saltus/body/body_model.h"
#include "saltus/evaluation/sampling.h"
#include "saltus/formats/motion_file.h"
#include "saltus/motion/motion.h"
#include "saltus/optim/option_table.h"

namespace saltus_python {

namespace py = pybind11;

// ---- errors (errors.cpp) ----

/// saltus.InputError (a ValueError) and saltus.OutputError (an OSError), and the translation of
/// the library's exceptions into them: what the CLI ends with status 2 raises InputError, what it
/// ends with 4 OutputError.
void bind_errors(py::module_& m);
/// Bad input named by `field` (an argument, "max_iter"): InputError("field: problem").
[[noreturn]] void throw_input_error(const std::string& field, const std::string& problem);

// ---- numpy (arrays.cpp) ----

/// A new C-ordered float64 array of `shape`, made read-only when `readonly`.
py::array_t<double> new_array(const std::vector<py::ssize_t>& shape);
/// Marks an array read-only (results are records of a run: a copy is writable).
py::array readonly(py::array a);
/// The numbers of `value` (anything numpy reads as float64) with exactly `shape`, every one
/// finite; InputError naming `field` otherwise (wrong shape, NaN, infinity, not numbers).
std::vector<double> numbers_from(py::handle value, const std::vector<py::ssize_t>& shape,
                                 const std::string& field);
Eigen::Vector3d vector3_from(py::handle value, const std::string& field);
/// [w, x, y, z], as Saltus's files write quaternions.
Eigen::Quaterniond quaternion_from(py::handle value, const std::string& field);
Eigen::Matrix3d matrix3_from(py::handle value, const std::string& field);
py::array_t<double> vector3_array(const Eigen::Vector3d& v);
py::array_t<double> quaternion_array(const Eigen::Quaterniond& q);
py::array_t<double> matrix3_array(const Eigen::Matrix3d& m);
py::array_t<double> doubles_array(const std::vector<double>& values);
/// Runs `write` (a library writer of a result folder) with the GIL released; returns the
/// result.json it wrote as Python objects.
py::object write_released(const std::function<nlohmann::json()>& write);
/// A JSON document as Python objects (dict, list, float, ...), read by Python's json module so
/// that every number is the one the file holds.
py::object python_json(const nlohmann::json& document);

// ---- models and motions (motions.cpp) ----

/// saltus.Model: a body model, editable (a segment's mass, CoM, inertia, joint centre); every
/// edit is checked by the library's model reader and undone when it refuses it.
struct PyModel {
  saltus::BodyModel model;
};
using ModelPtr = std::shared_ptr<PyModel>;

/// saltus.Motion: keyframes, take-off state and tolerances with the model they are for, editable
/// (a keyframe's time or pose, the take-off); every edit is checked by the library's motion
/// reader and undone when it refuses it. An edit drops a stored optimised spline (the keyframes
/// no longer describe it), as in the app.
struct PyMotion {
  std::string path;  ///< the file it was read from, "" when made in memory
  saltus::Motion motion;
  ModelPtr model;
  std::optional<saltus::TakeoffAdaptation> takeoff_adaptation;
};
using MotionPtr = std::shared_ptr<PyMotion>;

/// The motion and its model as the library takes them (a copy: the run does not see later edits).
saltus::MotionFile motion_file(const PyMotion& motion);
/// A Python object for a motion the library made (an optimised motion, an import's keyframes).
MotionPtr new_motion(const saltus::MotionFile& file);
ModelPtr new_model(const saltus::BodyModel& model);
/// A motion argument: a saltus.Motion, or a path (str or os.PathLike) read like `read_motion`.
MotionPtr motion_argument(py::handle value);
/// A model argument: None, a saltus.Model, or a bundled model's name or a model file's path.
std::optional<saltus::BodyModel> model_argument(py::handle value);
/// A path argument (str or os.PathLike) as text.
std::string path_argument(py::handle value, const std::string& field);
/// `file` flown by `model` instead of its own: the same keyframes, checked against it (CLI:
/// --model).
saltus::MotionFile with_model(saltus::MotionFile file, const saltus::BodyModel& model);
void bind_motions(py::module_& m);

// ---- options (options.cpp) ----

/// The keyword of an option: its flag in snake case ("--max-iter" -> "max_iter").
std::string option_keyword(const saltus::OptionSpec& spec);
/// The options of runs of `runs` (kEvaluation: samples and knots; kOptimization: all) given as
/// keyword arguments, each checked by the table (InputError naming the keyword); every other
/// keyword is a TypeError naming `function`, as Python's own for an unexpected argument.
saltus::OptionValues option_values(const py::kwargs& kwargs, saltus::OptionUse runs,
                                   const char* function);
/// The keyword parameters for a signature line: "formulation='relaxed', epsilon=100.0, ...".
std::string option_parameters(saltus::OptionUse runs);
/// One paragraph per option for a docstring: keyword, type, default, help, unit and range.
std::string option_docs(saltus::OptionUse runs);
/// A docstring whose first line Python reads as the signature (inspect.signature, help()).
std::string documented(const std::string& signature, const std::string& text);
void bind_options(py::module_& m);

// ---- sampled flights (flights.cpp) ----

/// Samples of a run with the model they were computed on: the arrays every result offers,
/// made on first use and kept (read-only).
struct Flight {
  std::shared_ptr<const std::vector<saltus::SampleRecord>> samples;
  std::shared_ptr<const saltus::BodyModel> model;
  /// Yeadon's angles per sample (degrees) when they come from a file; else computed.
  std::vector<Eigen::Vector3d> angles_deg;
  std::map<std::string, py::object> arrays;
  virtual ~Flight() = default;
};
void bind_flights(py::module_& m);

// ---- runs (runs.cpp), analyses (analyses.cpp), the other verbs (verbs.cpp) ----

void bind_runs(py::module_& m);
void bind_analyses(py::module_& m);
void bind_verbs(py::module_& m);

}  // namespace saltus_python
