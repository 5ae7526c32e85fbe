#pragma once
/// @file
/// The MuJoCo export (`saltus export --format mujoco`, docs/formats.md "MuJoCo"): the athlete as
/// an MJCF model (model.xml: a free root joint, a ball joint per segment, each segment's mass,
/// CoM and full inertia, display geoms of its drawing, one keyframe per sample) and its
/// trajectory in MuJoCo's coordinates (trajectory.csv: time, qpos, qvel, qacc per sample).
///
/// MuJoCo's world is z up: its x is Saltus's z (the way the athlete faces at identity), its y
/// Saltus's x (his left), its z Saltus's y (up). Every body frame is the Saltus segment's own, so
/// masses, CoMs, inertias and joint rotations keep their numbers; only the root's placement and
/// the free joint's linear velocity and acceleration are turned into MuJoCo's world. Quaternions
/// are w first, as MuJoCo stores them. Bodies come in depth-first order (children in model
/// order), MuJoCo's order of qpos and qvel.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "saltus/body/body_model.h"
#include "saltus/dynamics/body_state.h"

namespace saltus {

/// The rotation from Saltus's world to MuJoCo's (x forward, y left, z up).
Eigen::Quaterniond mujoco_from_saltus();

/// The segments in MuJoCo's body order: depth first from the root, children in model order.
std::vector<int> mujoco_body_order(const BodyModel& model);

/// One body state in MuJoCo's generalised coordinates, bodies in mujoco_body_order:
/// qpos = root position (world, m) and world_from_root (w x y z), then each ball joint's
/// parent_from_child (w x y z): 7 + 4·(n − 1) numbers; qvel = the root origin's velocity (world,
/// m/s) and angular velocity (root frame, rad/s), then each joint's relative angular velocity
/// (child frame, rad/s): 6 + 3·(n − 1); qacc = the time derivatives of qvel's numbers.
struct MujocoState {
  Eigen::VectorXd qpos, qvel, qacc;
};
MujocoState mujoco_state(const BodyModel& model, const BodyState<double>& state);

/// Names of qpos's and qvel's entries, in order: "root.x", "root.qw", "lumbar.qw", ... and
/// "root.vx", "root.wx", "lumbar.wx", ...; the CSV's columns prefix them with "qpos.", "qvel."
/// and "qacc." (qacc's entries are the derivatives of qvel's).
std::vector<std::string> mujoco_qpos_names(const BodyModel& model);
std::vector<std::string> mujoco_qvel_names(const BodyModel& model);

/// The MJCF model: bodies named as the segments, the free joint "root", ball joints named as
/// Saltus's joints, gravity −9.81 m/s² along z, display geoms (no collisions: contype and
/// conaffinity 0) in the app's shapes and colours, a ground plane at Saltus's y = 0, and one
/// <key> per state (its time, qpos and qvel). `title` names the model. The root body stands
/// upright at the first state's root position. Every number is written exactly.
/// @param times   one per state, s
/// @param states  sampled states of the motion, one per time
std::string mujoco_model_xml(const BodyModel& model, const std::string& title,
                             const std::vector<double>& times,
                             const std::vector<BodyState<double>>& states);

/// trajectory.csv: a header `t,qpos.root.x,...,qvel.root.vx,...,qacc.root.vx,...`, then one row
/// per state, every number in the shortest form that reads back exactly.
std::string mujoco_trajectory_csv(const BodyModel& model, const std::vector<double>& times,
                                  const std::vector<BodyState<double>>& states);

}  // namespace saltus
