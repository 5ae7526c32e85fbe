#include "saltus/formats/opensim_files.h"

#include <cmath>
#include <map>
#include <stdexcept>

#include "saltus/base/constants.h"
#include "saltus/base/text_format.h"
#include "saltus/body/drawn_parts.h"
#include "saltus/body/joint_coordinates.h"

namespace saltus {

namespace {

/// The root's rotations: Yeadon's somersault, tilt and twist (R = Rx·Rz·Ry, the Cardan order of
/// every joint), signs as they come.
JointCoordinates root_coordinates() {
  JointCoordinates root;
  root.kind = "root";
  root.coordinates = {JointCoordinate{"somersault", "", "", CardanAxis::x, 1.0, 0.0},
                      JointCoordinate{"tilt", "", "", CardanAxis::z, 1.0, 0.0},
                      JointCoordinate{"twist", "", "", CardanAxis::y, 1.0, 0.0}};
  return root;
}

JointCoordinates coordinates_of(const BodyModel& model, int segment) {
  return segment == 0 ? root_coordinates() : joint_coordinates(model, segment);
}

/// The axis a coordinate turns about, reversed for a coordinate that reads against the Cardan
/// angle (sign −1), so that every rotation is a LinearFunction of slope +1: OpenSim 4.0 took
/// only slope +1 as a rotation (later releases ±1; opensim-core issue #2062) and read any other
/// coordinate's degrees in a .mot as radians.
std::string axis_text(CardanAxis axis, double sign) {
  const std::string one = sign < 0 ? "-1" : "1";
  return axis == CardanAxis::x   ? one + " 0 0"
         : axis == CardanAxis::z ? "0 0 " + one
                                 : "0 " + one + " 0";
}

std::string os_numbers(const Eigen::Vector3d& v) {
  return exact_number(v.x()) + " " + exact_number(v.y()) + " " + exact_number(v.z());
}

/// An element on one line: <tag>text</tag>.
std::string line(const std::string& indent, const std::string& tag, const std::string& text) {
  return indent + "<" + tag + ">" + text + "</" + tag + ">\n";
}

std::string offset_frame(const std::string& indent, const std::string& name,
                         const std::string& parent, const Eigen::Vector3d& translation,
                         const std::string& inside = "") {
  return indent + "<PhysicalOffsetFrame name=\"" + xml_text(name) + "\">\n" +
         line(indent + "  ", "socket_parent", xml_text(parent)) +
         line(indent + "  ", "translation", os_numbers(translation)) +
         line(indent + "  ", "orientation", "0 0 0") + inside + indent + "</PhysicalOffsetFrame>\n";
}

/// One piece of display geometry on a frame of its own, centred at `center`.
std::string geometry_frame(const std::string& indent, const std::string& frame,
                           const std::string& body_path, const Eigen::Vector3d& center,
                           const std::string& type, const std::string& size,
                           const DrawingColour& colour) {
  const std::string in = indent + "    ";
  const std::string geometry =
      indent + "  <attached_geometry>\n" + in + "<" + type + " name=\"" + xml_text(frame) +
      "_geometry\">\n" + line(in + "  ", "socket_frame", "..") + in + "  <Appearance>\n" +
      line(in + "    ", "color", os_numbers(Eigen::Vector3d(colour.r, colour.g, colour.b))) + in +
      "  </Appearance>\n" + in + "  " + size + "\n" + in + "</" + type + ">\n" + indent +
      "  </attached_geometry>\n";
  return offset_frame(indent, frame, body_path, center, geometry);
}

/// A body's drawing: an ellipsoid per ellipsoid part, a cylinder and two spheres per capsule.
std::string body_geometry(const Segment& s, const std::string& indent) {
  const std::string path = "/bodyset/" + s.name;
  std::string out;
  std::map<std::string, int> used;
  const auto unique = [&](const std::string& name) {
    return used[name]++ ? name + "_" + std::to_string(used[name]) : name;
  };
  for (const DrawnPart& part : drawn_parts(s)) {
    const ShapePart& p = part.shape;
    if (p.type == "capsule") {
      const double half = 0.5 * std::abs(p.length);
      const std::string radius = "<radius>" + exact_number(p.radius) + "</radius>";
      out += geometry_frame(indent, unique(p.name), path, p.center, "Cylinder",
                            radius + "<half_height>" + exact_number(half) + "</half_height>",
                            part.colour);
      for (double end : {-half, half})
        out += geometry_frame(indent, unique(p.name + "_end"), path,
                              p.center + Eigen::Vector3d(0, end, 0), "Sphere", radius, part.colour);
    } else {
      out += geometry_frame(indent, unique(p.name), path, p.center, "Ellipsoid",
                            "<radii>" + os_numbers(p.radii) + "</radii>", part.colour);
    }
  }
  return out;
}

std::string coordinate_element(const std::string& indent, const std::string& name,
                               double default_value, double range) {
  return indent + "<Coordinate name=\"" + xml_text(name) + "\">\n" +
         line(indent + "  ", "default_value", exact_number(default_value)) +
         line(indent + "  ", "default_speed_value", "0") +
         line(indent + "  ", "range", exact_number(-range) + " " + exact_number(range)) +
         line(indent + "  ", "clamped", "false") + line(indent + "  ", "locked", "false") + indent +
         "</Coordinate>\n";
}

std::string transform_axis(const std::string& indent, const std::string& name,
                           const std::string& coordinate, const std::string& axis,
                           const std::string& function) {
  return indent + "<TransformAxis name=\"" + name + "\">\n" +
         line(indent + "  ", "coordinates", xml_text(coordinate)) +
         line(indent + "  ", "axis", axis) + indent + "  " + function + "\n" + indent +
         "</TransformAxis>\n";
}

std::string linear(double slope, double intercept) {
  return "<LinearFunction name=\"function\"><coefficients>" + exact_number(slope) + " " +
         exact_number(intercept) + "</coefficients></LinearFunction>";
}

/// The CustomJoint that moves segment `k` in its parent (the ground for the root).
std::string custom_joint(const BodyModel& model, int k, const std::string& indent) {
  const Segment& s = model.segments[k];
  const JointCoordinates jc = coordinates_of(model, k);
  const std::string parent = k == 0 ? "ground" : model.segments[s.parent].name;
  const std::string parent_path = k == 0 ? "/ground" : "/bodyset/" + parent;
  const std::string in = indent + "  ";
  std::string xml = indent + "<CustomJoint name=\"" + xml_text(s.joint) + "\">\n" +
                    line(in, "socket_parent_frame", xml_text(parent) + "_offset") +
                    line(in, "socket_child_frame", xml_text(s.name) + "_offset") + in +
                    "<coordinates>\n";
  for (const JointCoordinate& c : jc.coordinates)
    xml += coordinate_element(in + "  ", c.name, c.offset_rad, k == 0 ? 100.0 : 2 * kPi);
  if (k == 0)
    for (const char* t : {"root_tx", "root_ty", "root_tz"})
      xml += coordinate_element(in + "  ", t, 0.0, 1000.0);
  xml +=
      in + "</coordinates>\n" + in + "<frames>\n" +
      offset_frame(in + "  ", parent + "_offset", parent_path,
                   k == 0 ? Eigen::Vector3d::Zero() : s.joint_position) +
      offset_frame(in + "  ", s.name + "_offset", "/bodyset/" + s.name, Eigen::Vector3d::Zero()) +
      in + "</frames>\n" + in + "<SpatialTransform>\n";
  // angle = sign·(value − offset) about the axis: value − offset about sign·axis.
  for (int i = 0; i < 3; ++i) {
    const JointCoordinate& c = jc.coordinates[i];
    xml += transform_axis(in + "  ", "rotation" + std::to_string(i + 1), c.name,
                          axis_text(c.axis, c.sign), linear(1.0, -c.offset_rad));
  }
  const char* axes[3] = {"1 0 0", "0 1 0", "0 0 1"};
  const char* translations[3] = {"root_tx", "root_ty", "root_tz"};
  for (int i = 0; i < 3; ++i)
    xml += transform_axis(
        in + "  ", "translation" + std::to_string(i + 1), k == 0 ? translations[i] : "", axes[i],
        k == 0 ? linear(1.0, 0.0) : "<Constant name=\"function\"><value>0</value></Constant>");
  xml += in + "</SpatialTransform>\n" + indent + "</CustomJoint>\n";
  return xml;
}

void check_frames(const BodyModel& model, const std::vector<double>& times,
                  const std::vector<OpensimFrame>& frames) {
  const std::size_t count = opensim_coordinates(model).size();
  if (times.size() != frames.size() || frames.empty())
    throw std::invalid_argument("opensim export: one frame per time, at least one");
  for (const OpensimFrame& f : frames)
    if (static_cast<std::size_t>(f.values.size()) != count ||
        static_cast<std::size_t>(f.forces.size()) != count)
      throw std::invalid_argument("opensim export: a frame does not fit the model");
}

/// An OpenSim storage file (.mot, .sto): a header, then tab-separated rows.
std::string storage_text(const std::string& name, const std::vector<std::string>& columns,
                         const std::vector<double>& times,
                         const std::vector<std::vector<double>>& rows, bool degrees) {
  std::string out = name + "\nversion=1\nnRows=" + std::to_string(rows.size()) +
                    "\nnColumns=" + std::to_string(columns.size() + 1) +
                    "\ninDegrees=" + (degrees ? "yes" : "no") +
                    "\n\nWritten by Saltus (docs/formats.md, \"OpenSim\"). Units are S.I. units "
                    "(seconds, metres, newtons), angles in " +
                    (degrees ? "degrees" : "radians") + ".\n\nendheader\ntime";
  for (const std::string& c : columns)
    out += "\t" + c;
  out += "\n";
  for (std::size_t r = 0; r < rows.size(); ++r) {
    out += exact_number(times[r]);
    for (double v : rows[r])
      out += "\t" + exact_number(v);
    out += "\n";
  }
  return out;
}

}  // namespace

std::vector<OpensimCoordinate> opensim_coordinates(const BodyModel& model) {
  std::vector<OpensimCoordinate> out;
  for (int k = 0; k < model.size(); ++k) {
    for (const JointCoordinate& c : coordinates_of(model, k).coordinates)
      out.push_back({c.name, true});
    if (k == 0)
      for (const char* t : {"root_tx", "root_ty", "root_tz"})
        out.push_back({t, false});
  }
  return out;
}

OpensimFrame opensim_frame(const BodyModel& model, const BodyState<double>& state,
                           const SampleRecord& record) {
  const int n = model.size();
  if (static_cast<int>(state.joints.size()) != n ||
      static_cast<int>(record.joint_wrench.size()) != n)
    throw std::invalid_argument("opensim_frame: the state does not fit the model");
  OpensimFrame f;
  f.values.resize(3 * n + 3);
  f.forces.resize(3 * n + 3);
  int at = 0;
  for (int k = 0; k < n; ++k) {
    const JointState<double>& j = state.joints[k];
    // The moment the parent (for the root: the world) applies, segment frame, about the joint.
    const Eigen::Vector3d moment =
        k == 0 ? Eigen::Vector3d(record.root_wrench.tail<3>()) : record.joint_wrench[k].tail<3>();
    const JointCoordinateState c =
        joint_coordinate_state(coordinates_of(model, k), j.q, j.omega, moment);
    f.values.segment<3>(at) = c.value;
    f.forces.segment<3>(at) = c.moment;
    at += 3;
    if (k == 0) {
      // The translations move the root along the world's axes: their forces are the root force
      // in the world.
      f.values.segment<3>(at) = state.root_position;
      f.forces.segment<3>(at) = j.q.normalized() * Eigen::Vector3d(record.root_wrench.head<3>());
      at += 3;
    }
  }
  return f;
}

std::string opensim_model_xml(const BodyModel& model, const std::string& title) {
  std::string xml =
      "<?xml version=\"1.0\" encoding=\"UTF-8\" ?>\n<OpenSimDocument Version=\"40000\">\n"
      "  <Model name=\"" +
      xml_text(title) + "\">\n" +
      line("    ", "credits",
           "Written by Saltus from the body model " + xml_text(model.name) +
               " (docs/formats.md, \"OpenSim\"): " + xml_text(model.source)) +
      line("    ", "length_units", "meters") + line("    ", "force_units", "N") +
      line("    ", "gravity", "0 " + exact_number(-kStandardGravity) + " 0") +
      "    <Ground name=\"ground\" />\n    <BodySet name=\"bodyset\">\n      <objects>\n";
  for (const Segment& s : model.segments) {
    const Eigen::Matrix3d& i = s.inertia;
    xml += "        <Body name=\"" + xml_text(s.name) + "\">\n          <components>\n" +
           body_geometry(s, "            ") + "          </components>\n" +
           line("          ", "mass", exact_number(s.mass)) +
           line("          ", "mass_center", os_numbers(s.com)) +
           line("          ", "inertia",
                os_numbers(i.diagonal()) + " " + exact_number(i(0, 1)) + " " +
                    exact_number(i(0, 2)) + " " + exact_number(i(1, 2))) +
           "        </Body>\n";
  }
  xml += "      </objects>\n    </BodySet>\n    <JointSet name=\"jointset\">\n      <objects>\n";
  for (int k = 0; k < model.size(); ++k)
    xml += custom_joint(model, k, "        ");
  xml += "      </objects>\n    </JointSet>\n  </Model>\n</OpenSimDocument>\n";
  return xml;
}

std::string opensim_coordinates_mot(const BodyModel& model, const std::vector<double>& times,
                                    const std::vector<OpensimFrame>& frames) {
  check_frames(model, times, frames);
  const std::vector<OpensimCoordinate> coordinates = opensim_coordinates(model);
  std::vector<std::string> columns;
  for (const OpensimCoordinate& c : coordinates)
    columns.push_back(c.name);
  std::vector<std::vector<double>> rows;
  for (const OpensimFrame& f : frames) {
    std::vector<double> row(f.values.data(), f.values.data() + f.values.size());
    for (std::size_t i = 0; i < row.size(); ++i) {
      if (!coordinates[i].rotational) continue;
      row[i] = degrees_from_radians(row[i]);
      if (!rows.empty()) row[i] += 360.0 * std::round((rows.back()[i] - row[i]) / 360.0);
    }
    rows.push_back(row);
  }
  return storage_text("Coordinates", columns, times, rows, true);
}

std::string opensim_forces_sto(const BodyModel& model, const std::vector<double>& times,
                               const std::vector<OpensimFrame>& frames) {
  check_frames(model, times, frames);
  std::vector<std::string> columns;
  for (const OpensimCoordinate& c : opensim_coordinates(model))
    columns.push_back(c.name + (c.rotational ? "_moment" : "_force"));
  std::vector<std::vector<double>> rows;
  for (const OpensimFrame& f : frames)
    rows.emplace_back(f.forces.data(), f.forces.data() + f.forces.size());
  return storage_text("Inverse Dynamics Generalized Forces", columns, times, rows, false);
}

}  // namespace saltus
