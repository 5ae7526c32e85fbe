#include <cmath>
#include <sstream>

#include "module.h"

namespace saltus_python {

namespace {

std::string shape_text(const std::vector<py::ssize_t>& shape) {
  std::ostringstream out;
  out << '(';
  for (std::size_t i = 0; i < shape.size(); ++i)
    out << (i ? ", " : "") << shape[i];
  out << (shape.size() == 1 ? ",)" : ")");
  return out.str();
}

}  // namespace

py::array_t<double> new_array(const std::vector<py::ssize_t>& shape) {
  return py::array_t<double>(shape);
}

py::array readonly(py::array a) {
  a.attr("setflags")(py::arg("write") = false);
  return a;
}

std::vector<double> numbers_from(py::handle value, const std::vector<py::ssize_t>& shape,
                                 const std::string& field) {
  if (value.is_none() || py::isinstance<py::str>(value) || py::isinstance<py::bytes>(value))
    throw_input_error(field, "expected numbers of shape " + shape_text(shape) + ", got " +
                                 std::string(py::str(value.get_type().attr("__name__"))));
  py::array_t<double, py::array::c_style | py::array::forcecast> a;
  try {
    a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(value);
  } catch (const py::error_already_set&) {
    a = {};
  }
  if (!a) {
    PyErr_Clear();
    throw_input_error(field, "expected numbers of shape " + shape_text(shape));
  }
  std::vector<py::ssize_t> got(a.shape(), a.shape() + a.ndim());
  if (got != shape)
    throw_input_error(field, "expected shape " + shape_text(shape) + ", got " + shape_text(got));
  std::vector<double> out(a.data(), a.data() + a.size());
  for (std::size_t i = 0; i < out.size(); ++i)
    if (!std::isfinite(out[i]))
      throw_input_error(field, "element " + std::to_string(i) + " is " +
                                   (std::isnan(out[i]) ? "NaN" : "infinite") +
                                   "; every number must be finite");
  return out;
}

Eigen::Vector3d vector3_from(py::handle value, const std::string& field) {
  const std::vector<double> v = numbers_from(value, {3}, field);
  return {v[0], v[1], v[2]};
}

Eigen::Quaterniond quaternion_from(py::handle value, const std::string& field) {
  const std::vector<double> v = numbers_from(value, {4}, field);
  return {v[0], v[1], v[2], v[3]};
}

Eigen::Matrix3d matrix3_from(py::handle value, const std::string& field) {
  const std::vector<double> v = numbers_from(value, {3, 3}, field);
  Eigen::Matrix3d m;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      m(r, c) = v[static_cast<std::size_t>(3 * r + c)];
  return m;
}

py::array_t<double> vector3_array(const Eigen::Vector3d& v) {
  py::array_t<double> a = new_array({3});
  double* out = a.mutable_data();
  for (int i = 0; i < 3; ++i)
    out[i] = v[i];
  return a;
}

py::array_t<double> quaternion_array(const Eigen::Quaterniond& q) {
  py::array_t<double> a = new_array({4});
  double* out = a.mutable_data();
  out[0] = q.w();
  out[1] = q.x();
  out[2] = q.y();
  out[3] = q.z();
  return a;
}

py::array_t<double> matrix3_array(const Eigen::Matrix3d& m) {
  py::array_t<double> a = new_array({3, 3});
  double* out = a.mutable_data();
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      out[3 * r + c] = m(r, c);
  return a;
}

py::array_t<double> doubles_array(const std::vector<double>& values) {
  py::array_t<double> a = new_array({static_cast<py::ssize_t>(values.size())});
  std::copy(values.begin(), values.end(), a.mutable_data());
  return a;
}

py::object write_released(const std::function<nlohmann::json()>& write) {
  nlohmann::json written;
  {
    py::gil_scoped_release release;
    written = write();
  }
  return python_json(written);
}

py::object python_json(const nlohmann::json& document) {
  return py::module_::import("json").attr("loads")(document.dump());
}

}  // namespace saltus_python
