"""Motions and models edited in memory run as the same edits made on disk do; a bad value is
refused by the library's own readers and the object stays as it was; bad arrays raise."""

import copy
import json
import math

import numpy as np
import pytest

import saltus
from conftest import M1, assert_same_result, cli_result


def test_a_keyframe_time_edited_in_memory_evaluates_as_the_edited_file(tmp_path):
    motion = saltus.read_motion(M1)
    motion.keyframes[2].time = 1.1
    assert motion.keyframe_times[2] == 1.1
    motion.write(tmp_path / "edited.motion.json")
    ours = saltus.evaluate(motion).result
    cli = cli_result("evaluate", tmp_path / "edited.motion.json", "--out", tmp_path / "cli")
    ours["motion_file"] = cli["motion_file"]  # the file the CLI read is the one written here
    assert_same_result(ours, cli)
    assert saltus.evaluate(M1).average_root_force != saltus.evaluate(motion).average_root_force


def test_a_segment_s_mass_edited_in_memory_evaluates_as_the_edited_model_file(tmp_path):
    motion = saltus.read_motion(M1)
    thigh = motion.model.segment("thigh_r")
    before = thigh.mass
    thigh.mass = before * 1.5
    assert motion.model.segment("thigh_r").mass == before * 1.5  # the motion's model, shared
    motion.model.write(tmp_path / "heavy.model.json")
    ours = saltus.evaluate(motion).result
    cli = cli_result("evaluate", M1, "--model", tmp_path / "heavy.model.json",
                     "--out", tmp_path / "cli")
    assert_same_result(ours, cli)


def test_the_mass_study_s_edit_scales_mass_and_inertia():
    model = saltus.read_model("zatsiorsky-66kg")
    thigh = model.segment("thigh_l")
    mass, inertia = thigh.mass, thigh.inertia
    model.scale_segment_mass("thigh_l", 2.0)
    assert thigh.mass == 2.0 * mass
    assert np.array_equal(thigh.inertia, 2.0 * inertia)


def test_an_edit_the_library_refuses_leaves_the_object_as_it_was():
    motion = saltus.read_motion(M1)
    times = motion.keyframe_times.copy()
    with pytest.raises(saltus.InputError, match="keyframes"):
        motion.keyframes[1].time = 1.5  # after keyframe 2
    assert np.array_equal(motion.keyframe_times, times)
    model = motion.model
    with pytest.raises(saltus.InputError) as raised:
        model.segment("head_thorax" if "head_thorax" in model.segment_names
                      else model.segment_names[1]).mass = -1.0
    assert "mass" in str(raised.value)
    assert min(s.mass for s in model.segments) > 0
    with pytest.raises(saltus.InputError):
        model.segment(0).inertia = -np.eye(3)


@pytest.mark.parametrize("value", [
    [0.0, 1.0],                       # too short
    [[0.0, 1.0, 2.0]],                # (1, 3)
    [math.nan, 0.0, 0.0],             # NaN
    [math.inf, 0.0, 0.0],             # infinity
    "fast",                           # not numbers
    None,
    np.zeros((3, 3)),
    np.array(["a", "b", "c"]),
])
def test_a_bad_array_raises_and_never_crashes(value):
    motion = saltus.read_motion(M1)
    before = motion.takeoff_com_velocity.copy()
    with pytest.raises(saltus.InputError) as raised:
        motion.takeoff_com_velocity = value
    assert raised.value.file == "takeoff_com_velocity"
    assert np.array_equal(motion.takeoff_com_velocity, before)


def test_bad_rotations_raise():
    motion = saltus.read_motion(M1)
    k = motion.keyframes[1]
    n = len(motion.model.segment_names)
    with pytest.raises(saltus.InputError, match=r"shape \(%d, 4\)" % n):
        k.rotations = np.zeros((n, 3))
    bad = k.rotations.copy()
    bad[3, 0] = np.nan
    with pytest.raises(saltus.InputError, match="NaN"):
        k.rotations = bad
    bad = k.rotations.copy()
    bad[3] *= 2.0  # not a unit quaternion: the motion reader's check
    with pytest.raises(saltus.InputError, match="norm"):
        k.rotations = bad
    with pytest.raises(saltus.InputError):
        k.set_rotation("thigh_r", [1.0, 0.0, 0.0])
    with pytest.raises(KeyError):
        k.rotation("tail")
    with pytest.raises(IndexError):
        motion.keyframe(99)


def test_a_rotation_set_is_the_one_read_back():
    motion = saltus.read_motion(M1)
    q = np.array([math.cos(0.2), math.sin(0.2), 0.0, 0.0])
    motion.keyframes[1].set_rotation("knee_r" if False else "shank_r", q)
    assert np.allclose(motion.keyframes[1].rotation("shank_r"), q, atol=1e-15)


def test_copies_are_independent_and_an_edit_drops_the_stored_spline(m1_quick):
    optimised = m1_quick[0].motion
    assert optimised.optimised
    twin = copy.deepcopy(optimised)
    twin.keyframes[1].time = twin.keyframes[1].time + 0.01
    assert not twin.optimised and optimised.optimised
    other = optimised.copy()
    other.model.segment(0).mass += 1.0
    assert other.model.total_mass == optimised.model.total_mass + 1.0


def test_a_model_of_other_segments_is_refused(tmp_path):
    motion = saltus.read_motion(M1)
    motion.model = saltus.model_new(1.80, 80, "male")  # the same 13 segments: taken
    assert motion.model.name.startswith("de-leva")
    document = motion.model.to_json()
    document["segments"] = document["segments"][:-1]  # a leaf segment less
    (tmp_path / "short.model.json").write_text(json.dumps(document))
    short = saltus.read_model(tmp_path / "short.model.json")
    with pytest.raises(saltus.InputError):
        motion.model = short
    assert motion.model.name.startswith("de-leva")
