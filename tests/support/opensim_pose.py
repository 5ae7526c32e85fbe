#!/usr/bin/python3
"""An independent reader of Saltus's OpenSim export, for tests/cli/export_opensim_test.cpp.

OpenSim is not packaged for Debian, so the export is checked by reading it the way OpenSim 4
defines its files, with nothing of Saltus's code: the .osim's bodies, PhysicalOffsetFrames and
CustomJoints (a SpatialTransform: rotations about rotation1..3's axes applied body-fixed in order,
R = R1(f1)·R2(f2)·R3(f3), then the translations along translation1..3's axes in the parent frame,
as Simbody's MobilizedBody::FunctionBased computes X_FM for OpenSim's CustomJoint; each function a
LinearFunction "slope intercept" or a Constant), the .mot's coordinates (degrees when
inDegrees=yes, for the coordinates OpenSim calls Rotational) and the .sto's generalised forces
(named <coordinate>_moment for a Rotational coordinate, _force otherwise, as OpenSim's Inverse
Dynamics tool names them). A coordinate's motion type follows OpenSim 4.0's
CustomJoint::constructCoordinates: Rotational (or Translational) only when a rotation (or
translation) axis is a LinearFunction of it with slope exactly +1; anything else is Coupled and its
.mot values are taken as they are, not as degrees. Later releases also accept slope -1
(opensim-core issue #2062), so files that pass here read the same in every 4.x. It rebuilds every
body's pose at every row and compares it with Saltus's own trajectory.csv (from `saltus evaluate`
at the same times), each body's mass, CoM and inertia with Saltus's model.json, and the root's six
generalised forces with the CSV's root wrench (the force turned into the world; the moment's
components that do work on each rotation, by the transform's own angular-velocity Jacobian).

Usage: opensim_pose.py EXPORT_FOLDER TRAJECTORY_CSV MODEL_JSON
Prints one line of JSON with the worst differences found.
"""

import json
import sys
import xml.etree.ElementTree as ET

import numpy as np


def numbers(text):
    return np.array([float(v) for v in text.split()])


def rotation(axis, angle):
    """Rotation matrix by `angle` about the unit `axis` (Rodrigues)."""
    a = axis / np.linalg.norm(axis)
    k = np.array([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])
    return np.eye(3) + np.sin(angle) * k + (1 - np.cos(angle)) * (k @ k)


def body_fixed_xyz(angles):
    """OpenSim's PhysicalOffsetFrame orientation: body-fixed X-Y-Z angles."""
    x, y, z = np.eye(3)
    return rotation(x, angles[0]) @ rotation(y, angles[1]) @ rotation(z, angles[2])


def transform(r, p):
    t = np.eye(4)
    t[:3, :3] = r
    t[:3, 3] = p
    return t


class Function:
    """A TransformAxis's function of its coordinate (or a constant)."""

    def __init__(self, axis_element):
        linear = axis_element.find("LinearFunction")
        constant = axis_element.find("Constant")
        self.linear = linear is not None
        if linear is not None:
            self.slope, self.intercept = numbers(linear.find("coefficients").text)
        elif constant is not None:
            self.slope, self.intercept = 0.0, float(constant.find("value").text)
        else:
            raise ValueError("unsupported function in " + axis_element.get("name"))
        names = (axis_element.find("coordinates").text or "").split()
        self.coordinate = names[0] if names else None

    def value(self, q):
        return self.intercept + (self.slope * q[self.coordinate] if self.coordinate else 0.0)


def motion_types(joints):
    """Each coordinate's motion type as OpenSim 4.0 assigns it (see the module's docstring)."""
    types = {}
    for j in joints:
        for index, (_, f) in enumerate(j.rotations + j.translations):
            if not f.coordinate:
                continue
            if f.linear and f.slope == 1.0:
                types[f.coordinate] = "Rotational" if index < 3 else "Translational"
            else:
                types.setdefault(f.coordinate, "Coupled")
    return types


class Joint:
    def __init__(self, element):
        self.name = element.get("name")
        frames = {}
        for f in element.find("frames").findall("PhysicalOffsetFrame"):
            parent = f.find("socket_parent").text
            frames[f.get("name")] = (
                parent.split("/")[-1],
                transform(body_fixed_xyz(numbers(f.find("orientation").text)),
                          numbers(f.find("translation").text)))
        self.parent, self.parent_offset = frames[element.find("socket_parent_frame").text]
        self.child, self.child_offset = frames[element.find("socket_child_frame").text]
        axes = {a.get("name"): a for a in element.find("SpatialTransform").findall("TransformAxis")}
        self.rotations = [(numbers(axes["rotation%d" % i].find("axis").text),
                           Function(axes["rotation%d" % i])) for i in (1, 2, 3)]
        self.translations = [(numbers(axes["translation%d" % i].find("axis").text),
                              Function(axes["translation%d" % i])) for i in (1, 2, 3)]

    def mobilizer(self, q):
        """X_FM: the child's offset frame in the parent's."""
        r = np.eye(3)
        for axis, f in self.rotations:
            r = r @ rotation(axis, f.value(q))
        p = sum(f.value(q) * axis for axis, f in self.translations)
        return transform(r, p)

    def rotation_jacobian(self, q):
        """Per rotational coordinate, the angular velocity (child frame) of a unit rate:
        ω = Σ slope_i · (R_{i+1}·…·R_3)ᵀ · axis_i."""
        columns = {}
        for i, (axis, f) in enumerate(self.rotations):
            after = np.eye(3)
            for a, g in self.rotations[i + 1:]:
                after = after @ rotation(a, g.value(q))
            if f.coordinate:
                columns[f.coordinate] = f.slope * after.T @ (axis / np.linalg.norm(axis))
        return columns


def read_storage(path):
    with open(path) as f:
        lines = f.read().splitlines()
    end = lines.index("endheader")
    header = dict(line.split("=", 1) for line in lines[:end] if "=" in line)
    columns = lines[end + 1].split("\t")
    rows = np.array([[float(v) for v in line.split("\t")] for line in lines[end + 2:] if line])
    assert int(header["nRows"]) == len(rows) and int(header["nColumns"]) == len(columns)
    return header, columns, rows


def main(folder, trajectory_csv, model_json):
    model = ET.parse(folder + "/model.osim").getroot().find("Model")
    bodies = {b.get("name"): b for b in model.find("BodySet").find("objects").findall("Body")}
    joints = [Joint(j) for j in model.find("JointSet").find("objects").findall("CustomJoint")]
    types = motion_types(joints)
    rotational = {name for name, kind in types.items() if kind == "Rotational"}

    header, columns, rows = read_storage(folder + "/coordinates.mot")
    degrees = header["inDegrees"].strip() == "yes"

    csv_columns = open(trajectory_csv).readline().strip().split(",")
    csv = np.loadtxt(trajectory_csv, delimiter=",", skiprows=1, ndmin=2)
    col = {name: i for i, name in enumerate(csv_columns)}

    # Mass properties against Saltus's model file.
    saltus = {s["name"]: s for s in json.load(open(model_json))["segments"]}
    worst_mass = 0.0
    for name, b in bodies.items():
        s = saltus[name]
        inertia = s["inertia"] if len(s["inertia"]) == 6 else list(s["inertia"]) + [0, 0, 0]
        expected = np.concatenate([[s["mass"]], s["com"], inertia])
        found = np.concatenate([[float(b.find("mass").text)], numbers(b.find("mass_center").text),
                                numbers(b.find("inertia").text)])
        worst_mass = max(worst_mass, float(np.max(np.abs(found - expected))))

    worst_position = worst_rotation = 0.0
    matched = 0
    poses = []
    for row in rows:
        q = {}
        for name, v in zip(columns[1:], row[1:]):
            q[name] = np.radians(v) if degrees and name in rotational else v
        k = int(np.argmin(np.abs(csv[:, 0] - row[0])))
        if abs(csv[k, 0] - row[0]) > 1e-9:
            continue
        matched += 1
        world = {"ground": np.eye(4)}
        pending = list(joints)
        while pending:
            j = pending.pop(0)
            if j.parent not in world:
                pending.append(j)
                continue
            world[j.child] = (world[j.parent] @ j.parent_offset @ j.mobilizer(q)
                              @ np.linalg.inv(j.child_offset))
        poses.append((k, q, world))
        for name in bodies:
            x = world[name]
            p = csv[k, [col[name + ".x"], col[name + ".y"], col[name + ".z"]]]
            w, a, b, c = csv[k, [col[name + ".qw"], col[name + ".qx"], col[name + ".qy"],
                                 col[name + ".qz"]]]
            r = np.array([[1 - 2 * (b * b + c * c), 2 * (a * b - c * w), 2 * (a * c + b * w)],
                          [2 * (a * b + c * w), 1 - 2 * (a * a + c * c), 2 * (b * c - a * w)],
                          [2 * (a * c - b * w), 2 * (b * c + a * w), 1 - 2 * (a * a + b * b)]])
            worst_position = max(worst_position, float(np.linalg.norm(x[:3, 3] - p)))
            cosine = np.clip((np.trace(r.T @ x[:3, :3]) - 1) / 2, -1, 1)
            worst_rotation = max(worst_rotation, float(np.degrees(np.arccos(cosine))))

    # The root's generalised forces against the CSV's root wrench (root frame, root origin).
    _, force_columns, forces = read_storage(folder + "/inverse_dynamics.sto")
    expected_columns = [name + ("_moment" if name in rotational else "_force")
                        for name in columns[1:]]
    misnamed = [a for a, b in zip(force_columns[1:], expected_columns) if a != b]
    if len(force_columns) != len(columns):
        misnamed.append("%d columns for %d coordinates" % (len(force_columns) - 1,
                                                           len(columns) - 1))
    root = next(j for j in joints if j.parent == "ground")
    worst_force = 0.0
    scale = 0.0
    for k, q, world in poses:
        f = forces[int(np.argmin(np.abs(forces[:, 0] - csv[k, 0])))]
        found = dict(zip(force_columns[1:], f[1:]))
        r = world[root.child][:3, :3]
        force = r @ csv[k, [col["root_fx"], col["root_fy"], col["root_fz"]]]
        moment = csv[k, [col["root_mx"], col["root_my"], col["root_mz"]]]
        expected = {}
        for axis, g in root.translations:
            expected[g.coordinate + "_force"] = g.slope * axis @ force
        for name, column in root.rotation_jacobian(q).items():
            expected[name + "_moment"] = column @ moment
        for name, value in expected.items():
            worst_force = max(worst_force, abs(found[name] - value))
            scale = max(scale, abs(value))

    print(json.dumps({
        "rows": len(rows), "matched_rows": matched, "bodies": sorted(bodies),
        "coordinates": columns[1:], "in_degrees": degrees,
        "motion_types": {kind: sum(1 for t in types.values() if t == kind)
                         for kind in sorted(set(types.values()))},
        "misnamed_forces": misnamed,
        "worst_position_m": worst_position, "worst_rotation_deg": worst_rotation,
        "worst_mass_property_error": worst_mass,
        "worst_root_force_error": worst_force, "largest_root_force": scale}))


if __name__ == "__main__":
    main(*sys.argv[1:4])
