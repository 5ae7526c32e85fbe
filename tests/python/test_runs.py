"""evaluate, simulate and optimize give what the CLI gives for the same input."""

import filecmp
import json

import numpy as np
import pytest

import saltus
from conftest import M1, M2, assert_same_result, cli_result, run_cli


def test_evaluate_is_saltus_evaluate(tmp_path):
    ours = saltus.evaluate(M1, samples=401, knots_per_interval=2)
    cli = cli_result("evaluate", M1, "--samples", 401, "--knots-per-interval", 2,
                     "--out", tmp_path / "cli")
    assert_same_result(ours.result, cli)
    assert ours.average_root_force == cli["before"]["avg_root_force"]
    assert ours.figures == cli["before"]


def test_an_evaluation_writes_the_cli_s_folder_byte_for_byte(tmp_path):
    run_cli("evaluate", M1, "--out", tmp_path / "cli", "-q")
    written = saltus.evaluate(M1).write(tmp_path / "py")
    assert written == json.loads((tmp_path / "py" / "result.json").read_text())
    for name in ("result.json", "trajectory.csv", "model.json"):
        assert filecmp.cmp(tmp_path / "cli" / name, tmp_path / "py" / name, shallow=False), name


def test_the_arrays_are_the_trajectory_csv_s_columns(tmp_path):
    e = saltus.evaluate(M1, samples=201)
    e.write(tmp_path / "e")
    folder = saltus.read_result(tmp_path / "e")
    for name in ("times", "root_force", "root_moment", "residual_force", "residual_moment",
                 "com", "segment_positions", "segment_rotations", "somersault_tilt_twist"):
        assert np.array_equal(getattr(e, name), getattr(folder.before, name)), name
    n, s = len(e), len(e.segment_names)
    assert e.times.shape == (n,) and e.root_force.shape == (n, 3)
    assert e.segment_positions.shape == (n, s, 3) and e.segment_rotations.shape == (n, s, 4)
    assert e.joint_moments.shape == (n, s - 1, 3) and len(e.joint_names) == s - 1
    assert folder.before.joint_moments is None  # trajectory.csv holds no joint loads
    assert not e.root_force.flags.writeable


def test_the_strength_shares_over_time_peak_where_result_json_says():
    e = saltus.evaluate(M1, samples=2001)
    shares = e.strength_shares
    assert shares.shape == (len(e), len(e.joint_names)) and (shares >= 0).all()
    peaks = e.result["joint_strength"]["before"]["joints"]
    for j, joint in enumerate(e.joint_names):
        # The dense check's peak is the largest over more points than the 2001 samples.
        peak = peaks[joint]["share"]
        assert shares[:, j].max() <= peak * (1 + 1e-9), joint
        assert shares[:, j].max() == pytest.approx(peak, rel=0.02), joint


def test_the_average_root_force_is_the_paper_s_sqrt_j_over_6():
    e = saltus.evaluate(M1, samples=2001)
    # Independently of the dense check: the trapezoidal rule on 2001 samples of the arrays.
    f = np.hstack([e.root_force, e.root_moment])
    j = np.trapz((f ** 2).sum(axis=1), e.times) / e.times[-1]
    assert e.average_root_force == pytest.approx(np.sqrt(j / 6), rel=1e-3)


def test_simulate_is_saltus_simulate_also_on_another_athlete(tmp_path):
    assert_same_result(saltus.simulate(M1).result,
                       cli_result("simulate", M1, "--out", tmp_path / "own"))
    ours = saltus.simulate(M1, "zatsiorsky-66kg", takeoff="keep-momentum", samples=51)
    cli = cli_result("simulate", M1, "--model", "zatsiorsky-66kg", "--takeoff", "keep-momentum",
                     "--samples", 51, "--out", tmp_path / "other")
    assert_same_result(ours.result, cli)
    junior = saltus.model_new(1.45, 38, "female", name="junior")
    junior.write(tmp_path / "junior.model.json")
    ours = saltus.simulate(M1, junior)
    cli = cli_result("simulate", M1, "--model", tmp_path / "junior.model.json",
                     "--out", tmp_path / "junior")
    # The CLI names the model file it was given; the module's motion names the model.
    cli["motion_file"] = ours.result["motion_file"]
    assert without_model_reference(ours.result) == without_model_reference(cli)
    assert ours.result["takeoff_adaptation"]["rule"] == "same spin"


def without_model_reference(result):
    return {k: v for k, v in result.items() if k != "model_reference"}


def test_optimize_is_saltus_optimize(m1_optimised, tmp_path):
    ours, cli, cli_dir = m1_optimised
    assert ours.solved and ours.status == "solved"
    assert_same_result(ours.result, cli)
    assert ours.after.average_root_force == cli["after"]["avg_root_force"]
    assert list(ours.after.keyframe_times) == cli["keyframe_times_after"]
    ours.write(tmp_path / "py")
    for name in ("trajectory_before.csv", "trajectory_after.csv", "optimized.motion.json",
                 "model.json"):
        assert filecmp.cmp(cli_dir / name, tmp_path / "py" / name, shallow=False), name


def test_the_optimised_motion_reloads_to_the_same_figures(m1_optimised, tmp_path):
    ours, _, _ = m1_optimised
    ours.motion.write(tmp_path / "m1-opt.motion.json")
    again = saltus.evaluate(saltus.read_motion(tmp_path / "m1-opt.motion.json"))
    assert again.average_root_force == pytest.approx(ours.after.average_root_force, rel=1e-9)
    assert saltus.evaluate(ours.motion).average_root_force == pytest.approx(
        ours.after.average_root_force, rel=1e-9)


def test_options_reach_the_optimiser_as_the_cli_s_flags_do(tmp_path):
    ours = saltus.optimize(M2, formulation="strict", epsilon=50, no_timing=True,
                           knots_per_interval=1, max_iter=15, samples=51)
    done = run_cli("optimize", M2, "--formulation", "strict", "--epsilon", 50, "--no-timing",
                   "--knots-per-interval", 1, "--max-iter", 15, "--samples", 51, "--out",
                   tmp_path / "cli", "-q", expect=0 if ours.solved else 3)
    cli = json.loads((tmp_path / "cli" / "result.json").read_text())
    assert_same_result(ours.result, cli)
    assert cli["formulation"] == "strict" and cli["timing_optimized"] is False
    assert ours.iterations <= 15


BAD_OPTIONS = [
    ("max_iter", -1, "--max-iter", "-1"),
    ("max_iter", 2.5, "--max-iter", "2.5"),
    ("tol", 0, "--tol", "0"),
    ("knots_per_interval", "sometimes", "--knots-per-interval", "sometimes"),
    ("knots_per_interval", 51, "--knots-per-interval", "51"),
    ("formulation", "loose", "--formulation", "loose"),
    ("samples", 1, "--samples", "1"),
    ("threads", 0, "--threads", "0"),
    ("max_joint_turn", 400.0, "--max-joint-turn", "400"),
]


@pytest.mark.parametrize("keyword,value,flag,text", BAD_OPTIONS)
def test_a_value_the_cli_refuses_the_module_refuses_with_the_same_words(
        keyword, value, flag, text, tmp_path):
    with pytest.raises(saltus.InputError) as raised:
        saltus.optimize(M1, **{keyword: value})
    assert raised.value.file == keyword
    assert str(raised.value).startswith(keyword + ": ")
    done = run_cli("optimize", M1, flag, text, "--out", tmp_path / "x", expect=2)
    problem = raised.value.problem.split(" (allowed")[0].replace(" whole number", "")
    assert problem.split()[-1] in done.stderr, (problem, done.stderr)
    assert not (tmp_path / "x").exists()


def test_words_only_optimisations_take_are_refused_by_evaluate():
    with pytest.raises(saltus.InputError, match="knots_per_interval.*optimisations only"):
        saltus.evaluate(M1, knots_per_interval="auto")
    with pytest.raises(TypeError, match="unexpected keyword argument 'max_iter'"):
        saltus.evaluate(M1, max_iter=3)
    with pytest.raises(saltus.InputError, match="no_timing"):
        saltus.optimize(M1, no_timing="yes")
    with pytest.raises(saltus.InputError, match="max_iter"):
        saltus.optimize(M1, max_iter=True)


def test_a_bad_file_raises_input_error_naming_file_and_field(tmp_path):
    bad = json.loads(open(M1).read())
    bad["keyframes"][2]["time"] = "soon"
    path = tmp_path / "bad.motion.json"
    path.write_text(json.dumps(bad))
    with pytest.raises(saltus.InputError) as raised:
        saltus.read_motion(path)
    done = run_cli("evaluate", path, "--out", tmp_path / "x", expect=2)
    assert str(raised.value) in done.stderr
    assert raised.value.file == str(path) and "keyframes" in raised.value.field
    with pytest.raises(saltus.InputError):
        saltus.read_motion(tmp_path / "missing.motion.json")
    with pytest.raises(saltus.InputError):
        saltus.read_model("no-such-model")


def test_a_folder_saltus_did_not_write_is_never_replaced(tmp_path):
    (tmp_path / "mine").mkdir()
    (tmp_path / "mine" / "notes.txt").write_text("keep me")
    with pytest.raises(saltus.InputError):
        saltus.evaluate(M1).write(tmp_path / "mine")
    assert (tmp_path / "mine" / "notes.txt").read_text() == "keep me"
