#pragma once
/// @file
/// The OpenSim export (`saltus export --format opensim`, docs/formats.md "OpenSim"): the athlete
/// as an OpenSim 4.x model (model.osim: bodies with Saltus's masses, CoMs and inertias, each
/// joint a CustomJoint), its coordinates over time (coordinates.mot, degrees) and the
/// generalised forces that drive them (inverse_dynamics.sto, as OpenSim's Inverse Dynamics tool
/// names its columns). Written to OpenSim 4.0's format (Version 40000); not opened in OpenSim
/// here (it is not packaged for Debian): tests/support/opensim_pose.py rebuilds every segment's
/// pose from these files instead.
///
/// Every joint's coordinates are body/joint_coordinates.h's, the one definition the strength
/// report uses: rotations about the segment's x, z, y axes in that order (OpenSim's rotation1,
/// 2, 3, body-fixed), each a LinearFunction of slope +1 of its coordinate about sign·axis
/// (OpenSim 4.0 takes no other slope as a rotation: its .mot degrees would be read as radians). The
/// root is a free joint of six coordinates, `somersault`, `tilt`, `twist` (Yeadon's angles,
/// R = Rx·Rz·Ry, evaluation/yeadon_angles.h) and `root_tx`, `root_ty`, `root_tz` (the root origin
/// in the world, m): a CustomJoint, as OpenSim's gait models give the pelvis, rather than
/// OpenSim's FreeJoint, whose X-Y-Z angles lock at 90° of twist. OpenSim's world is Saltus's
/// (y up, gravity −9.81 m/s² along y), its body frames the segments' own.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "saltus/body/body_model.h"
#include "saltus/dynamics/body_state.h"
#include "saltus/evaluation/sampling.h"

namespace saltus {

/// One coordinate of the exported model.
struct OpensimCoordinate {
  std::string name;  ///< "somersault", "root_tx", "hip_flexion_r", ...
  bool rotational = true;
};

/// The model's coordinates in order: the root's six, then each joint's three (model order,
/// Cardan order x, z, y).
std::vector<OpensimCoordinate> opensim_coordinates(const BodyModel& model);

/// The coordinates at one sample: values (rad, m) and the generalised forces that drive them
/// (N·m, N: the moment's and force's components that do work on each coordinate, what OpenSim's
/// Inverse Dynamics reports), from the state and its inverse dynamics.
struct OpensimFrame {
  Eigen::VectorXd values;
  Eigen::VectorXd forces;
};
OpensimFrame opensim_frame(const BodyModel& model, const BodyState<double>& state,
                           const SampleRecord& record);

/// model.osim: the OpenSim 4.0 model named `title`, with display geometry in the app's shapes
/// (ellipsoids; capsules as a cylinder and two spheres) and colours.
std::string opensim_model_xml(const BodyModel& model, const std::string& title);

/// coordinates.mot: time and every coordinate, rotations in degrees (`inDegrees=yes`), each
/// rotation made continuous over the frames (whole turns added), so that OpenSim's interpolation
/// between rows turns the short way and the root's angles count turns.
std::string opensim_coordinates_mot(const BodyModel& model, const std::vector<double>& times,
                                    const std::vector<OpensimFrame>& frames);

/// inverse_dynamics.sto: time and every coordinate's generalised force, `<name>_moment` (N·m)
/// for a rotation and `<name>_force` (N) for a translation.
std::string opensim_forces_sto(const BodyModel& model, const std::vector<double>& times,
                               const std::vector<OpensimFrame>& frames);

}  // namespace saltus
