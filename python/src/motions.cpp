#include <pybind11/stl.h>

#include <utility>

#include "module.h"
#include "saltus/formats/model_file.h"
#include "saltus/formats/motion_file.h"
#include "saltus/use_cases/athlete_models.h"
#include "saltus/use_cases/captures.h"

namespace saltus_python {

namespace {

/// A segment of a saltus.Model, by index: reads and edits go to the model itself.
struct SegmentView {
  ModelPtr owner;
  int index = 0;
  saltus::Segment& segment() const {
    return owner->model.segments.at(static_cast<std::size_t>(index));
  }
};

/// A keyframe of a saltus.Motion, by index.
struct KeyframeView {
  MotionPtr owner;
  int index = 0;
  saltus::Keyframe& keyframe() const {
    return owner->motion.keyframes.at(static_cast<std::size_t>(index));
  }
};

/// Applies `edit` to the model, then runs the library's model reader on it; when the reader
/// refuses, the model is restored and its InputError raised.
template <typename Edit>
void edit_model(PyModel& m, Edit&& edit) {
  saltus::BodyModel before = m.model;
  edit(m.model);
  try {
    saltus::parse_body_model(saltus::body_model_to_json(m.model),
                             "the edited model \"" + m.model.name + "\"");
  } catch (...) {
    m.model = std::move(before);
    throw;
  }
}

/// Applies `edit` to the motion (dropping a stored optimised spline), then runs the library's
/// motion reader on it; the reader's motion (quaternions normalised) is kept, or on refusal the
/// motion is restored and the InputError raised.
template <typename Edit>
void edit_motion(PyMotion& m, Edit&& edit) {
  saltus::Motion edited = m.motion;
  edited.spline.reset();
  edit(edited);
  m.motion = saltus::parse_motion(saltus::motion_to_json(edited, m.model->model),
                                  "the edited motion \"" + edited.name + "\"", m.model->model);
}

int checked_index(int index, int size, const char* what) {
  const int i = index < 0 ? index + size : index;
  if (i < 0 || i >= size)
    throw py::index_error(std::string(what) + " index " + std::to_string(index) +
                          " out of range (" + std::to_string(size) + ")");
  return i;
}

int segment_index(const saltus::BodyModel& model, py::handle key) {
  if (py::isinstance<py::str>(key)) {
    const std::string name = py::cast<std::string>(key);
    const int i = model.segment_index(name);
    if (i < 0) throw py::key_error("model " + model.name + " has no segment '" + name + "'");
    return i;
  }
  return checked_index(py::cast<int>(key), model.size(), "segment");
}

std::vector<std::string> segment_names(const saltus::BodyModel& model) {
  std::vector<std::string> out;
  for (const saltus::Segment& s : model.segments)
    out.push_back(s.name);
  return out;
}

py::array_t<double> rotations_array(const saltus::Keyframe& k) {
  py::array_t<double> a = new_array({static_cast<py::ssize_t>(k.rotations.size()), 4});
  double* out = a.mutable_data();
  for (const Eigen::Quaterniond& q : k.rotations) {
    *out++ = q.w();
    *out++ = q.x();
    *out++ = q.y();
    *out++ = q.z();
  }
  return a;
}

}  // namespace

saltus::MotionFile motion_file(const PyMotion& m) {
  saltus::MotionFile f;
  f.path = m.path;
  f.motion = m.motion;
  f.model = m.model->model;
  f.takeoff_adaptation = m.takeoff_adaptation;
  return f;
}

MotionPtr new_motion(const saltus::MotionFile& file) {
  auto m = std::make_shared<PyMotion>();
  m->path = file.path;
  m->motion = file.motion;
  m->model = new_model(file.model);
  m->takeoff_adaptation = file.takeoff_adaptation;
  return m;
}

ModelPtr new_model(const saltus::BodyModel& model) {
  auto m = std::make_shared<PyModel>();
  m->model = model;
  return m;
}

std::string path_argument(py::handle value, const std::string& field) {
  if (py::isinstance<py::str>(value)) return py::cast<std::string>(value);
  if (py::hasattr(value, "__fspath__")) {
    const py::object path = value.attr("__fspath__")();
    if (py::isinstance<py::str>(path)) return py::cast<std::string>(path);
  }
  throw_input_error(field, "expected a path (str or os.PathLike), got " +
                               std::string(py::str(value.get_type().attr("__name__"))));
}

MotionPtr motion_argument(py::handle value) {
  if (py::isinstance<PyMotion>(value)) return py::cast<MotionPtr>(value);
  return new_motion(saltus::load_motion_or_capture(path_argument(value, "motion")));
}

std::optional<saltus::BodyModel> model_argument(py::handle value) {
  if (value.is_none()) return std::nullopt;
  if (py::isinstance<PyModel>(value)) return py::cast<ModelPtr>(value)->model;
  return saltus::load_model_argument(path_argument(value, "model"));
}

saltus::MotionFile with_model(saltus::MotionFile file, const saltus::BodyModel& model) {
  saltus::parse_motion(saltus::motion_to_json(file.motion, model),
                       file.path.empty() ? "the motion \"" + file.motion.name + "\"" : file.path,
                       model);
  file.model = model;
  file.takeoff_adaptation.reset();
  return file;
}

void bind_motions(py::module_& m) {
  py::class_<SegmentView>(m, "Segment",
                          "One segment of a Model: reading and setting its fields edits the "
                          "model. Lengths in m, masses in kg, inertias in kg·m², in the "
                          "segment's frame.")
      .def_property_readonly("name", [](const SegmentView& s) { return s.segment().name; })
      .def_property_readonly(
          "joint", [](const SegmentView& s) { return s.segment().joint; },
          "name of the joint to the parent ('root' for the root)")
      .def_property_readonly(
          "parent",
          [](const SegmentView& s) -> py::object {
            const int p = s.segment().parent;
            if (p < 0) return py::none();
            return py::str(s.owner->model.segments[static_cast<std::size_t>(p)].name);
          },
          "the parent segment's name, None for the root")
      .def_property(
          "mass", [](const SegmentView& s) { return s.segment().mass; },
          [](SegmentView& s, double v) {
            edit_model(*s.owner, [&](saltus::BodyModel& b) {
              b.segments[static_cast<std::size_t>(s.index)].mass = v;
            });
          },
          "kg (> 0); the inertia is left as it is (Model.scale_segment_mass scales both)")
      .def_property(
          "com", [](const SegmentView& s) { return vector3_array(s.segment().com); },
          [](SegmentView& s, py::handle v) {
            const Eigen::Vector3d com = vector3_from(v, s.segment().name + ".com");
            edit_model(*s.owner, [&](saltus::BodyModel& b) {
              b.segments[static_cast<std::size_t>(s.index)].com = com;
            });
          },
          "centre of mass, segment frame, m, shape (3,)")
      .def_property(
          "inertia", [](const SegmentView& s) { return matrix3_array(s.segment().inertia); },
          [](SegmentView& s, py::handle v) {
            const Eigen::Matrix3d inertia = matrix3_from(v, s.segment().name + ".inertia");
            edit_model(*s.owner, [&](saltus::BodyModel& b) {
              b.segments[static_cast<std::size_t>(s.index)].inertia = inertia;
            });
          },
          "about the CoM, segment axes, kg·m², shape (3, 3), symmetric positive definite")
      .def_property(
          "joint_position",
          [](const SegmentView& s) { return vector3_array(s.segment().joint_position); },
          [](SegmentView& s, py::handle v) {
            const Eigen::Vector3d p = vector3_from(v, s.segment().name + ".joint_position");
            edit_model(*s.owner, [&](saltus::BodyModel& b) {
              b.segments[static_cast<std::size_t>(s.index)].joint_position = p;
            });
          },
          "joint centre in the parent's frame, m, shape (3,) (the root's is unused)")
      .def("__repr__", [](const SegmentView& s) {
        return "<saltus.Segment " + s.segment().name + " of " + s.owner->model.name + ", " +
               saltus::format_number("%.4g kg>", s.segment().mass);
      });

  py::class_<PyModel, ModelPtr>(
      m, "Model",
      "A body model: segments (parent before child) joined by ball joints, the root free. "
      "Read with read_model, made by model_new, model_yeadon or Model.scaled; editable in "
      "memory (a segment's mass, CoM, inertia, joint centre), each edit checked by the "
      "library's model reader.")
      .def_property(
          "name", [](const PyModel& p) { return p.model.name; },
          [](PyModel& p, const std::string& name) {
            edit_model(p, [&](saltus::BodyModel& b) { b.name = name; });
          })
      .def_property_readonly(
          "source", [](const PyModel& p) { return p.model.source; }, "where the numbers come from")
      .def_property_readonly(
          "total_mass", [](const PyModel& p) { return p.model.total_mass(); }, "kg")
      .def_property_readonly("segment_names",
                             [](const PyModel& p) { return segment_names(p.model); })
      .def_property_readonly("joint_names",
                             [](const PyModel& p) {
                               std::vector<std::string> out;
                               for (const saltus::Segment& s : p.model.segments)
                                 out.push_back(s.joint);
                               return out;
                             })
      .def_property_readonly("segments",
                             [](const ModelPtr& p) {
                               std::vector<SegmentView> out;
                               for (int i = 0; i < p->model.size(); ++i)
                                 out.push_back({p, i});
                               return out;
                             })
      .def(
          "segment",
          [](const ModelPtr& p, py::handle key) {
            return SegmentView{p, segment_index(p->model, key)};
          },
          py::arg("name"),
          documented("segment($self, name)",
                     "The segment of this name (or index), a view that edits the model.")
              .c_str())
      .def(
          "scale_segment_mass",
          [](PyModel& p, const std::string& segment, double factor) {
            if (!segment.empty() && p.model.segment_index(segment) < 0)
              throw py::key_error("model " + p.model.name + " has no segment '" + segment + "'");
            edit_model(p, [&](saltus::BodyModel& b) {
              b = saltus::scale_segment_mass(b, segment, factor);
            });
          },
          py::arg("segment"), py::arg("factor"),
          documented("scale_segment_mass($self, segment, factor)",
                     "Multiplies one segment's mass and inertia (every segment's for '') by "
                     "factor > 0, in place (the mass study's edit).")
              .c_str())
      .def(
          "copy", [](const PyModel& p) { return new_model(p.model); },
          documented("copy($self)", "An independent copy.").c_str())
      .def("__copy__", [](const PyModel& p) { return new_model(p.model); })
      .def("__deepcopy__", [](const PyModel& p, py::handle) { return new_model(p.model); })
      .def(
          "write",
          [](const PyModel& p, py::handle path) {
            const std::string out = path_argument(path, "path");
            py::gil_scoped_release release;
            saltus::write_athlete_model(out, p.model);
          },
          py::arg("path"),
          documented("write($self, path)",
                     "Writes the model file (saltus-model/1) atomically; an existing file is "
                     "replaced only when it is a Saltus model file.")
              .c_str())
      .def(
          "to_json",
          [](const PyModel& p) { return python_json(saltus::body_model_to_json(p.model)); },
          documented("to_json($self)",
                     "The model as its file holds it (saltus-model/1), as a dict.")
              .c_str())
      .def("__repr__", [](const PyModel& p) {
        return "<saltus.Model " + p.model.name + ": " + std::to_string(p.model.size()) +
               saltus::format_number(" segments, %.4g kg>", p.model.total_mass());
      });

  py::class_<KeyframeView>(m, "Keyframe",
                           "One keyframe of a Motion: setting its fields edits the motion "
                           "(checked by the library's motion reader).")
      .def_property(
          "time", [](const KeyframeView& k) { return k.keyframe().time; },
          [](KeyframeView& k, double t) {
            edit_motion(*k.owner, [&](saltus::Motion& motion) {
              motion.keyframes[static_cast<std::size_t>(k.index)].time = t;
            });
          },
          "s; the first is 0, times strictly increase")
      .def_property(
          "rotations", [](const KeyframeView& k) { return rotations_array(k.keyframe()); },
          [](KeyframeView& k, py::handle v) {
            const int n = k.owner->model->model.size();
            const std::vector<double> q = numbers_from(v, {n, 4}, "rotations");
            edit_motion(*k.owner, [&](saltus::Motion& motion) {
              auto& r = motion.keyframes[static_cast<std::size_t>(k.index)].rotations;
              for (std::size_t i = 0; i < r.size(); ++i)
                r[i] = Eigen::Quaterniond(q[4 * i], q[4 * i + 1], q[4 * i + 2], q[4 * i + 3]);
            });
          },
          "shape (segments, 4): each segment's rotation relative to its parent (the root's: to "
          "the world) as [w, x, y, z], unit norm")
      .def(
          "rotation",
          [](const KeyframeView& k, py::handle segment) {
            return quaternion_array(k.keyframe().rotations.at(
                static_cast<std::size_t>(segment_index(k.owner->model->model, segment))));
          },
          py::arg("segment"),
          documented("rotation($self, segment)",
                     "One segment's rotation relative to its parent, [w, x, y, z].")
              .c_str())
      .def(
          "set_rotation",
          [](KeyframeView& k, py::handle segment, py::handle value) {
            const int i = segment_index(k.owner->model->model, segment);
            const Eigen::Quaterniond q = quaternion_from(value, "rotation");
            edit_motion(*k.owner, [&](saltus::Motion& motion) {
              motion.keyframes[static_cast<std::size_t>(k.index)]
                  .rotations[static_cast<std::size_t>(i)] = q;
            });
          },
          py::arg("segment"), py::arg("rotation"),
          documented("set_rotation($self, segment, rotation)",
                     "Sets one segment's rotation relative to its parent, [w, x, y, z].")
              .c_str())
      .def_property(
          "root_position",
          [](const KeyframeView& k) -> py::object {
            const auto& p = k.keyframe().root_position;
            if (!p) return py::none();
            return vector3_array(*p);
          },
          [](KeyframeView& k, py::handle v) {
            std::optional<Eigen::Vector3d> p;
            if (!v.is_none()) p = vector3_from(v, "root_position");
            edit_motion(*k.owner, [&](saltus::Motion& motion) {
              motion.keyframes[static_cast<std::size_t>(k.index)].root_position = p;
            });
          },
          "the root's (abdomen origin's) world position, m, shape (3,), or None: from the CoM "
          "parabola")
      .def("__repr__", [](const KeyframeView& k) {
        return "<saltus.Keyframe " + std::to_string(k.index) + " of " + k.owner->motion.name +
               saltus::format_number(" at %.4g s>", k.keyframe().time);
      });

  py::class_<PyMotion, MotionPtr>(
      m, "Motion",
      "A keyframed motion with the body model it is for: keyframe times and poses, the take-off "
      "state of the CoM, the keyframe tolerances. Read with read_motion (or import_capture), "
      "made by optimize (Optimization.motion); editable in memory, each edit checked by the "
      "library's motion reader, and run again without touching disk.")
      .def_property(
          "name", [](const PyMotion& p) { return p.motion.name; },
          [](PyMotion& p, const std::string& name) {
            edit_motion(p, [&](saltus::Motion& motion) { motion.name = name; });
          })
      .def_property_readonly(
          "path", [](const PyMotion& p) { return p.path; },
          "the file it was read from ('' when made in memory)")
      .def_property(
          "model", [](const PyMotion& p) { return p.model; },
          [](PyMotion& p, py::handle value) {
            const std::optional<saltus::BodyModel> model = model_argument(value);
            if (!model) throw_input_error("model", "a motion needs a model");
            saltus::MotionFile file = with_model(motion_file(p), *model);
            p.model =
                py::isinstance<PyModel>(value) ? py::cast<ModelPtr>(value) : new_model(file.model);
            p.takeoff_adaptation.reset();
          },
          "the body model (shared: editing it edits what this motion runs on); set another "
          "with the same segments, or a bundled model's name or a model file")
      .def_property_readonly(
          "flight_time", [](const PyMotion& p) { return p.motion.flight_time(); }, "s")
      .def_property_readonly("keyframes",
                             [](const MotionPtr& p) {
                               std::vector<KeyframeView> out;
                               for (std::size_t i = 0; i < p->motion.keyframes.size(); ++i)
                                 out.push_back({p, static_cast<int>(i)});
                               return out;
                             })
      .def(
          "keyframe",
          [](const MotionPtr& p, int index) {
            return KeyframeView{
                p, checked_index(index, static_cast<int>(p->motion.keyframes.size()), "keyframe")};
          },
          py::arg("index"),
          documented("keyframe($self, index)",
                     "The keyframe of this index, a view that edits "
                     "the motion.")
              .c_str())
      .def_property_readonly(
          "keyframe_times",
          [](const PyMotion& p) {
            std::vector<double> t;
            for (const saltus::Keyframe& k : p.motion.keyframes)
              t.push_back(k.time);
            return doubles_array(t);
          },
          "s, shape (keyframes,)")
      .def_property(
          "takeoff_com_position",
          [](const PyMotion& p) { return vector3_array(p.motion.takeoff.com_position); },
          [](PyMotion& p, py::handle v) {
            const Eigen::Vector3d x = vector3_from(v, "takeoff_com_position");
            edit_motion(p, [&](saltus::Motion& motion) { motion.takeoff.com_position = x; });
          },
          "the CoM at take-off, world, m, shape (3,)")
      .def_property(
          "takeoff_com_velocity",
          [](const PyMotion& p) { return vector3_array(p.motion.takeoff.com_velocity); },
          [](PyMotion& p, py::handle v) {
            const Eigen::Vector3d x = vector3_from(v, "takeoff_com_velocity");
            edit_motion(p, [&](saltus::Motion& motion) { motion.takeoff.com_velocity = x; });
          },
          "the CoM's velocity at take-off, world, m/s, shape (3,)")
      .def_property(
          "takeoff_angular_momentum",
          [](const PyMotion& p) -> py::object {
            if (!p.motion.takeoff.angular_momentum) return py::none();
            return vector3_array(*p.motion.takeoff.angular_momentum);
          },
          [](PyMotion& p, py::handle v) {
            std::optional<Eigen::Vector3d> x;
            if (!v.is_none()) x = vector3_from(v, "takeoff_angular_momentum");
            edit_motion(p, [&](saltus::Motion& motion) { motion.takeoff.angular_momentum = x; });
          },
          "about the CoM, world, kg·m²/s, shape (3,), or None: simulate then uses the constant "
          "nearest the motion's own L(t)")
      .def_property(
          "tolerances",
          [](const PyMotion& p) {
            return py::make_tuple(p.motion.tolerances.translation_m,
                                  p.motion.tolerances.quaternion);
          },
          [](PyMotion& p, std::pair<double, double> t) {
            edit_motion(p, [&](saltus::Motion& motion) {
              motion.tolerances.translation_m = t.first;
              motion.tolerances.quaternion = t.second;
            });
          },
          "(root translation m per coordinate, quaternion distance): the keyframe tolerances "
          "of the relaxed model (paper eqs. 2-3)")
      .def_property_readonly(
          "optimised", [](const PyMotion& p) { return p.motion.spline.has_value(); },
          "whether it stores an optimised trajectory (an edit drops it)")
      .def(
          "copy", [](const PyMotion& p) { return new_motion(motion_file(p)); },
          documented("copy($self)", "An independent copy (its model copied too).").c_str())
      .def("__copy__", [](const PyMotion& p) { return new_motion(motion_file(p)); })
      .def("__deepcopy__", [](const PyMotion& p, py::handle) { return new_motion(motion_file(p)); })
      .def(
          "write",
          [](const PyMotion& p, py::handle path) {
            const std::string out = path_argument(path, "path");
            const saltus::MotionFile f = motion_file(p);
            py::gil_scoped_release release;
            saltus::save_motion_file(out, f.motion, f.model);
          },
          py::arg("path"),
          documented("write($self, path)",
                     "Writes the motion file (saltus-motion/1) atomically; an existing file is "
                     "replaced only when it is a Saltus motion file. Its \"model\" field names "
                     "the model as the motion was read (a bundled name stays valid anywhere).")
              .c_str())
      .def(
          "to_json",
          [](const PyMotion& p) {
            return python_json(saltus::motion_to_json(p.motion, p.model->model));
          },
          documented("to_json($self)",
                     "The motion as its file holds it (saltus-motion/1), as a dict.")
              .c_str())
      .def("__repr__", [](const PyMotion& p) {
        return "<saltus.Motion " + p.motion.name + " on " + p.model->model.name + ": " +
               std::to_string(p.motion.keyframes.size()) + " keyframes" +
               saltus::format_number(", %.4g s>", p.motion.flight_time());
      });

  m.def(
      "read_motion",
      [](py::handle path, py::handle model) {
        const std::string file = path_argument(path, "path");
        std::string model_reference;
        if (!model.is_none()) model_reference = path_argument(model, "model");
        saltus::MotionFile loaded;
        {
          py::gil_scoped_release release;
          loaded = saltus::load_motion_or_capture(file, model_reference);
        }
        return new_motion(loaded);
      },
      py::arg("path"), py::arg("model") = py::none(),
      documented("read_motion(path, model=None)",
                 "Reads a motion file (*.motion.json) with the model it names, or a BVH capture "
                 "(*.bvh: imported with the defaults, its picked keyframes), as the CLI's verbs "
                 "do. `model`: a bundled model's name or a model file instead of the motion's "
                 "own (the CLI's --model). Raises InputError naming the file and field.")
          .c_str());
  m.def(
      "read_model",
      [](py::handle path) {
        const std::string file = path_argument(path, "path");
        saltus::BodyModel loaded;
        {
          py::gil_scoped_release release;
          loaded = saltus::load_model_argument(file);
        }
        return new_model(loaded);
      },
      py::arg("path"),
      documented("read_model(path)",
                 "Reads a model file (*.model.json) or a bundled model by name "
                 "(resources/models/, e.g. 'zatsiorsky-66kg'). Raises InputError naming the file "
                 "and field.")
          .c_str());
}

}  // namespace saltus_python
