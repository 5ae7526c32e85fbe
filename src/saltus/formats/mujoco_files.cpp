#include "saltus/formats/mujoco_files.h"

#include <cmath>
#include <functional>
#include <initializer_list>
#include <map>
#include <stdexcept>

#include "saltus/base/constants.h"
#include "saltus/base/text_format.h"
#include "saltus/body/drawn_parts.h"

namespace saltus {

namespace {

/// Numbers separated by spaces, each exact.
template <typename Vector>
std::string mj_numbers(const Vector& v) {
  std::string out;
  for (Eigen::Index i = 0; i < v.size(); ++i) {
    if (i) out += ' ';
    out += exact_number(v[i]);
  }
  return out;
}

std::string mj_quaternion(const Eigen::Quaterniond& q) {
  return mj_numbers(Eigen::Vector4d(q.w(), q.x(), q.y(), q.z()));
}

void check_states(const BodyModel& model, const std::vector<double>& times,
                  const std::vector<BodyState<double>>& states) {
  if (times.size() != states.size() || states.empty())
    throw std::invalid_argument("mujoco export: one state per time, at least one");
  for (const BodyState<double>& s : states)
    if (static_cast<int>(s.joints.size()) != model.size())
      throw std::invalid_argument("mujoco export: a state does not fit the model");
}

/// The display geoms of a segment: its drawing, no collisions.
std::string mj_geoms(const Segment& segment, const std::string& indent) {
  std::string out;
  std::map<std::string, int> used;
  for (const DrawnPart& part : drawn_parts(segment)) {
    const ShapePart& p = part.shape;
    std::string name = segment.name + "." + p.name;
    if (used[name]++) name += "." + std::to_string(used[name]);
    out += indent + "<geom name=\"" + xml_text(name) + "\" ";
    if (p.type == "capsule" && std::abs(p.length) > 0) {
      const Eigen::Vector3d half(0, 0.5 * p.length, 0);
      Eigen::Matrix<double, 6, 1> ends;
      ends.head<3>() = p.center - half;
      ends.tail<3>() = p.center + half;
      out += "type=\"capsule\" fromto=\"" + mj_numbers(ends) + "\" size=\"" +
             exact_number(p.radius) + "\"";
    } else if (p.type == "capsule") {
      out += "type=\"sphere\" pos=\"" + mj_numbers(p.center) + "\" size=\"" +
             exact_number(p.radius) + "\"";
    } else {
      out += "type=\"ellipsoid\" pos=\"" + mj_numbers(p.center) + "\" size=\"" +
             mj_numbers(p.radii) + "\"";
    }
    const DrawingColour& c = part.colour;
    out += " rgba=\"" + mj_numbers(Eigen::Vector4d(c.r, c.g, c.b, 1.0)) +
           "\" contype=\"0\" conaffinity=\"0\"/>\n";
  }
  return out;
}

/// The inertial element: Saltus's mass, CoM and inertia (the matrix's entries, as MuJoCo's
/// fullinertia takes them: M11 M22 M33 M12 M13 M23).
std::string mj_inertial(const Segment& s, const std::string& indent) {
  const Eigen::Matrix3d& i = s.inertia;
  Eigen::Matrix<double, 6, 1> full;
  full << i(0, 0), i(1, 1), i(2, 2), i(0, 1), i(0, 2), i(1, 2);
  return indent + "<inertial pos=\"" + mj_numbers(s.com) + "\" mass=\"" + exact_number(s.mass) +
         "\" fullinertia=\"" + mj_numbers(full) + "\"/>\n";
}

/// "<joint>.<name>" for every joint in MuJoCo's order: the root's `translation` names, then
/// every joint's (the root's included) `rotation` names.
std::vector<std::string> mj_coordinate_names(const BodyModel& model,
                                             std::initializer_list<const char*> translation,
                                             std::initializer_list<const char*> rotation) {
  std::vector<std::string> names;
  for (int segment : mujoco_body_order(model)) {
    const std::string& joint = model.segments[segment].joint;
    if (segment == 0)
      for (const char* c : translation)
        names.push_back(joint + "." + c);
    for (const char* c : rotation)
      names.push_back(joint + "." + c);
  }
  return names;
}

}  // namespace

Eigen::Quaterniond mujoco_from_saltus() {
  Eigen::Matrix3d r;
  // Columns: where Saltus's x (left), y (up), z (forward) go in MuJoCo's world.
  r << 0, 0, 1,  //
      1, 0, 0,   //
      0, 1, 0;
  return Eigen::Quaterniond(r);
}

std::vector<int> mujoco_body_order(const BodyModel& model) {
  std::vector<int> order;
  std::function<void(int)> visit = [&](int segment) {
    order.push_back(segment);
    for (int child = 0; child < model.size(); ++child)
      if (model.segments[child].parent == segment) visit(child);
  };
  if (model.size() > 0) visit(0);
  return order;
}

MujocoState mujoco_state(const BodyModel& model, const BodyState<double>& state) {
  const int n = model.size();
  if (n < 1 || static_cast<int>(state.joints.size()) != n)
    throw std::invalid_argument("mujoco_state: the state does not fit the model");
  const Eigen::Quaterniond w = mujoco_from_saltus();
  MujocoState out;
  out.qpos.resize(7 + 4 * (n - 1));
  out.qvel.resize(6 + 3 * (n - 1));
  out.qacc.resize(out.qvel.size());
  const JointState<double>& root = state.joints[0];
  const Eigen::Quaterniond q0 = w * root.q;
  const Eigen::Matrix3d world = w.toRotationMatrix();
  out.qpos.head<3>() = world * state.root_position;
  out.qpos.segment<4>(3) << q0.w(), q0.x(), q0.y(), q0.z();
  out.qvel.head<3>() = world * state.root_velocity;
  out.qvel.segment<3>(3) = root.omega;
  out.qacc.head<3>() = world * state.root_acceleration;
  out.qacc.segment<3>(3) = root.alpha;
  int p = 7, v = 6;
  for (int segment : mujoco_body_order(model)) {
    if (segment == 0) continue;
    const JointState<double>& j = state.joints[segment];
    out.qpos.segment<4>(p) << j.q.w(), j.q.x(), j.q.y(), j.q.z();
    out.qvel.segment<3>(v) = j.omega;
    out.qacc.segment<3>(v) = j.alpha;
    p += 4;
    v += 3;
  }
  return out;
}

std::vector<std::string> mujoco_qpos_names(const BodyModel& model) {
  return mj_coordinate_names(model, {"x", "y", "z"}, {"qw", "qx", "qy", "qz"});
}

std::vector<std::string> mujoco_qvel_names(const BodyModel& model) {
  return mj_coordinate_names(model, {"vx", "vy", "vz"}, {"wx", "wy", "wz"});
}

std::string mujoco_model_xml(const BodyModel& model, const std::string& title,
                             const std::vector<double>& times,
                             const std::vector<BodyState<double>>& states) {
  check_states(model, times, states);
  std::string xml = "<mujoco model=\"" + xml_text(title) + "\">\n";
  xml +=
      "  <!-- Written by Saltus: the athlete's segments as bodies (Saltus's segment frames, "
      "masses and inertias), MuJoCo's world z up (x = Saltus z, y = Saltus x, z = Saltus y), "
      "one key per sample of the motion. docs/formats.md, \"MuJoCo\". -->\n";
  xml += "  <compiler angle=\"radian\" inertiafromgeom=\"false\"/>\n";
  xml += "  <option gravity=\"0 0 " + exact_number(-kStandardGravity) + "\"/>\n";
  xml += "  <visual><headlight ambient=\"0.4 0.4 0.4\" diffuse=\"0.6 0.6 0.6\"/></visual>\n";
  xml += "  <worldbody>\n";
  xml +=
      "    <geom name=\"ground\" type=\"plane\" size=\"10 10 0.1\" rgba=\"0.85 0.85 0.8 1\" "
      "contype=\"0\" conaffinity=\"0\"/>\n";
  // Bodies nest depth first; a body's element closes when the walk leaves its subtree.
  const Eigen::Quaterniond w = mujoco_from_saltus();
  std::function<void(int, int)> body = [&](int segment, int depth) {
    const Segment& s = model.segments[segment];
    const std::string indent(2 * depth, ' ');
    xml += indent + "<body name=\"" + xml_text(s.name) + "\" pos=\"";
    if (segment == 0) {
      const Eigen::Vector3d position = w.toRotationMatrix() * states.front().root_position;
      xml += mj_numbers(position) + "\" quat=\"" + mj_quaternion(w) + "\">\n" + indent +
             "  <freejoint name=\"" + xml_text(s.joint) + "\"/>\n";
    } else {
      xml += mj_numbers(s.joint_position) + "\">\n" + indent + "  <joint name=\"" +
             xml_text(s.joint) + "\" type=\"ball\"/>\n";
    }
    xml += mj_inertial(s, indent + "  ");
    xml += mj_geoms(s, indent + "  ");
    for (int child = 0; child < model.size(); ++child)
      if (model.segments[child].parent == segment) body(child, depth + 1);
    xml += indent + "</body>\n";
  };
  body(0, 2);
  xml += "  </worldbody>\n  <keyframe>\n";
  for (std::size_t k = 0; k < states.size(); ++k) {
    const MujocoState q = mujoco_state(model, states[k]);
    xml += "    <key time=\"" + exact_number(times[k]) + "\" qpos=\"" + mj_numbers(q.qpos) +
           "\" qvel=\"" + mj_numbers(q.qvel) + "\"/>\n";
  }
  xml += "  </keyframe>\n</mujoco>\n";
  return xml;
}

std::string mujoco_trajectory_csv(const BodyModel& model, const std::vector<double>& times,
                                  const std::vector<BodyState<double>>& states) {
  check_states(model, times, states);
  std::string csv = "t";
  for (const std::string& name : mujoco_qpos_names(model))
    csv += ",qpos." + name;
  const std::vector<std::string> velocities = mujoco_qvel_names(model);
  for (const char* prefix : {",qvel.", ",qacc."})
    for (const std::string& name : velocities)
      csv += prefix + name;
  csv += '\n';
  for (std::size_t k = 0; k < states.size(); ++k) {
    const MujocoState q = mujoco_state(model, states[k]);
    csv += exact_number(times[k]);
    for (const Eigen::VectorXd* v : {&q.qpos, &q.qvel, &q.qacc})
      for (Eigen::Index i = 0; i < v->size(); ++i)
        csv += ',' + exact_number((*v)[i]);
    csv += '\n';
  }
  return csv;
}

}  // namespace saltus
