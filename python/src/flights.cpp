#include <pybind11/stl.h>

#include <functional>

#include "module.h"
#include "saltus/base/constants.h"
#include "saltus/evaluation/yeadon_angles.h"

namespace saltus_python {

namespace {

using Samples = std::vector<saltus::SampleRecord>;

/// An (n, 3) array of one vector per sample.
py::array_t<double> per_sample3(
    const Samples& s, const std::function<Eigen::Vector3d(const saltus::SampleRecord&)>& f) {
  py::array_t<double> a = new_array({static_cast<py::ssize_t>(s.size()), 3});
  double* out = a.mutable_data();
  for (const saltus::SampleRecord& r : s) {
    const Eigen::Vector3d v = f(r);
    *out++ = v.x();
    *out++ = v.y();
    *out++ = v.z();
  }
  return a;
}

/// The array `name` of `flight`, made by `make` on first use and kept read-only.
py::object cached(Flight& flight, const char* name, const std::function<py::array()>& make) {
  auto it = flight.arrays.find(name);
  if (it == flight.arrays.end()) it = flight.arrays.emplace(name, readonly(make())).first;
  return it->second;
}

/// Joint loads (n, segments − 1, 3): force (first = 0) or moment (first = 3) of every joint but
/// the root's; None when the samples hold none (a trajectory CSV read back).
py::object joint_loads(Flight& f, const char* name, int first) {
  const Samples& s = *f.samples;
  if (s.empty() || s.front().joint_wrench.empty()) return py::none();
  return cached(f, name, [&]() {
    const py::ssize_t joints = static_cast<py::ssize_t>(f.model->segments.size()) - 1;
    py::array_t<double> a = new_array({static_cast<py::ssize_t>(s.size()), joints, 3});
    double* out = a.mutable_data();
    for (const saltus::SampleRecord& r : s)
      for (py::ssize_t j = 1; j <= joints; ++j)
        for (int i = 0; i < 3; ++i)
          *out++ = r.joint_wrench[static_cast<std::size_t>(j)][first + i];
    return a;
  });
}

}  // namespace

void bind_flights(py::module_& m) {
  py::class_<Flight, std::shared_ptr<Flight>>(
      m, "Flight",
      "Samples of a motion over its flight, as numpy arrays (read-only, made on first use): "
      "every result's base (Evaluation, Simulation, a result folder's trajectories). n samples "
      "uniform on [0, T], both ends included (the `samples` option).")
      .def_property_readonly(
          "times",
          [](Flight& f) {
            return cached(f, "times", [&]() {
              py::array_t<double> a = new_array({static_cast<py::ssize_t>(f.samples->size())});
              double* out = a.mutable_data();
              for (const saltus::SampleRecord& r : *f.samples)
                *out++ = r.time;
              return a;
            });
          },
          "s, shape (n,)")
      .def_property_readonly(
          "root_force",
          [](Flight& f) {
            return cached(f, "root_force", [&]() {
              return per_sample3(*f.samples, [](const saltus::SampleRecord& r) {
                return Eigen::Vector3d(r.root_wrench.head<3>());
              });
            });
          },
          "the paper's F1..F3: the force the world must apply at the root for the motion to "
          "happen (0 in true flight), N, root frame, shape (n, 3)")
      .def_property_readonly(
          "root_moment",
          [](Flight& f) {
            return cached(f, "root_moment", [&]() {
              return per_sample3(*f.samples, [](const saltus::SampleRecord& r) {
                return Eigen::Vector3d(r.root_wrench.tail<3>());
              });
            });
          },
          "the paper's F4..F6: the moment at the root, N·m, root frame about the root origin, "
          "shape (n, 3)")
      .def_property_readonly(
          "residual_force",
          [](Flight& f) {
            return cached(f, "residual_force", [&]() {
              return per_sample3(*f.samples, [](const saltus::SampleRecord& r) {
                return Eigen::Vector3d(r.residual.head<3>());
              });
            });
          },
          "the same wrench's force in the world frame, dP/dt − m·g, N, shape (n, 3)")
      .def_property_readonly(
          "residual_moment",
          [](Flight& f) {
            return cached(f, "residual_moment", [&]() {
              return per_sample3(*f.samples, [](const saltus::SampleRecord& r) {
                return Eigen::Vector3d(r.residual.tail<3>());
              });
            });
          },
          "its moment in the world frame about the whole-body CoM, dL/dt, N·m, shape (n, 3)")
      .def_property_readonly(
          "com",
          [](Flight& f) {
            return cached(f, "com", [&]() {
              return per_sample3(*f.samples, [](const saltus::SampleRecord& r) { return r.com; });
            });
          },
          "whole-body centre of mass, world, m, shape (n, 3)")
      .def_property_readonly(
          "com_velocity",
          [](Flight& f) {
            return cached(f, "com_velocity", [&]() {
              return per_sample3(*f.samples,
                                 [](const saltus::SampleRecord& r) { return r.com_velocity; });
            });
          },
          "m/s, world, shape (n, 3) (zeros for a trajectory CSV read back)")
      .def_property_readonly(
          "angular_momentum",
          [](Flight& f) {
            return cached(f, "angular_momentum", [&]() {
              return per_sample3(*f.samples,
                                 [](const saltus::SampleRecord& r) { return r.angular_momentum; });
            });
          },
          "about the CoM, world, kg·m²/s, shape (n, 3) (zeros for a trajectory CSV read back)")
      .def_property_readonly(
          "segment_positions",
          [](Flight& f) {
            return cached(f, "segment_positions", [&]() {
              const Samples& s = *f.samples;
              const py::ssize_t n = static_cast<py::ssize_t>(f.model->segments.size());
              py::array_t<double> a = new_array({static_cast<py::ssize_t>(s.size()), n, 3});
              double* out = a.mutable_data();
              for (const saltus::SampleRecord& r : s)
                for (const Eigen::Vector3d& p : r.segment_position) {
                  *out++ = p.x();
                  *out++ = p.y();
                  *out++ = p.z();
                }
              return a;
            });
          },
          "each segment's origin (its joint centre), world, m, shape (n, segments, 3)")
      .def_property_readonly(
          "segment_rotations",
          [](Flight& f) {
            return cached(f, "segment_rotations", [&]() {
              const Samples& s = *f.samples;
              const py::ssize_t n = static_cast<py::ssize_t>(f.model->segments.size());
              py::array_t<double> a = new_array({static_cast<py::ssize_t>(s.size()), n, 4});
              double* out = a.mutable_data();
              for (const saltus::SampleRecord& r : s)
                for (const Eigen::Quaterniond& q : r.segment_rotation) {
                  // One hemisphere (w >= 0), as trajectory.csv writes them.
                  const double sign = q.w() < 0 ? -1.0 : 1.0;
                  *out++ = sign * q.w();
                  *out++ = sign * q.x();
                  *out++ = sign * q.y();
                  *out++ = sign * q.z();
                }
              return a;
            });
          },
          "each segment's orientation, world_from_segment, as [w, x, y, z] with w >= 0 (as "
          "trajectory.csv), shape (n, segments, 4)")
      .def_property_readonly(
          "joint_forces", [](Flight& f) { return joint_loads(f, "joint_forces", 0); },
          "the force each joint's parent applies on its segment, N, in the segment's frame, "
          "shape (n, segments − 1, 3) in joint_names' order (the root left out); None when "
          "the samples hold none (a trajectory CSV read back)")
      .def_property_readonly(
          "joint_moments", [](Flight& f) { return joint_loads(f, "joint_moments", 3); },
          "the moment each joint's parent applies on its segment, N·m, in the segment's frame "
          "about the joint centre, shape (n, segments − 1, 3); None as joint_forces")
      .def_property_readonly(
          "strength_shares",
          [](Flight& f) -> py::object {
            const Samples& s = *f.samples;
            if (s.empty() || s.front().strength_share.empty()) return py::none();
            return cached(f, "strength_shares", [&]() {
              const py::ssize_t joints = static_cast<py::ssize_t>(f.model->segments.size()) - 1;
              py::array_t<double> a = new_array({static_cast<py::ssize_t>(s.size()), joints});
              double* out = a.mutable_data();
              for (const saltus::SampleRecord& r : s)
                for (py::ssize_t j = 1; j <= joints; ++j)
                  *out++ = r.strength_share[static_cast<std::size_t>(j)];
              return a;
            });
          },
          "each joint's largest share of the athlete's maximal moment at that angle and speed "
          "(1: all the muscles can give; 0 where no direction has a strength curve), "
          "dimensionless, shape (n, segments − 1) in joint_names' order; None when the samples "
          "hold none (a trajectory CSV read back)")
      .def_property_readonly(
          "somersault_tilt_twist",
          [](Flight& f) {
            return cached(f, "somersault_tilt_twist", [&]() {
              std::vector<Eigen::Vector3d> deg = f.angles_deg;
              if (deg.empty()) {
                std::vector<Eigen::Quaterniond> roots;
                for (const saltus::SampleRecord& r : *f.samples)
                  roots.push_back(r.segment_rotation.front());
                for (const Eigen::Vector3d& a : saltus::unwrapped_angles(roots))
                  deg.push_back(a * saltus::kDegreesPerRadian);
              }
              py::array_t<double> a = new_array({static_cast<py::ssize_t>(deg.size()), 3});
              double* out = a.mutable_data();
              for (const Eigen::Vector3d& v : deg) {
                *out++ = v.x();
                *out++ = v.y();
                *out++ = v.z();
              }
              return a;
            });
          },
          "Yeadon's angles of the root, degrees, shape (n, 3): somersault φ, tilt θ, twist ψ "
          "(world_from_root = Rx(φ)·Rz(θ)·Ry(ψ); φ and ψ continuous, so they count turns), as "
          "trajectory.csv's somersault_deg, tilt_deg, twist_deg")
      .def_property_readonly("segment_names",
                             [](const Flight& f) {
                               std::vector<std::string> out;
                               for (const saltus::Segment& s : f.model->segments)
                                 out.push_back(s.name);
                               return out;
                             })
      .def_property_readonly(
          "joint_names",
          [](const Flight& f) {
            std::vector<std::string> out;
            for (std::size_t i = 1; i < f.model->segments.size(); ++i)
              out.push_back(f.model->segments[i].joint);
            return out;
          },
          "the joints of joint_forces and joint_moments, in order (the root left out)")
      .def("__len__", [](const Flight& f) { return f.samples->size(); });
}

}  // namespace saltus_python
