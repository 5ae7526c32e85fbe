"""The analyses, import and export, the athletes' models, result folders and the studies give
what the CLI gives for the same input."""

import csv
import filecmp
import json
import warnings

import pytest

import saltus
from conftest import (ARMS, BACKFLIP_BVH, M1, M2, YEADON_MALE, assert_same_result, cli_result,
                      run_cli)


def test_analyse_twist_is_saltus_analyse_twist(tmp_path):
    ours = saltus.analyse_twist(ARMS, samples=51)
    cli = cli_result("analyse", "twist", ARMS, "--samples", 51, "--out", tmp_path / "cli")
    assert_same_result(ours.result, cli)
    assert sum(s["tilt_deg"] for s in ours.shares) == pytest.approx(ours.total_tilt_deg, abs=1e-6)
    assert "arm" in ours.sentence
    ours.write(tmp_path / "py")
    for name in ("twist.csv", "twist.md", "result.json"):
        assert filecmp.cmp(tmp_path / "cli" / name, tmp_path / "py" / name, shallow=False), name


def test_what_if_is_saltus_analyse_what_if(tmp_path):
    ours = saltus.what_if(M2, tuck_later=0.03, tuck_scale=1.1)
    cli = cli_result("analyse", "what-if", M2, "--tuck-later", 0.03, "--tuck-scale", 1.1,
                     "--out", tmp_path / "cli")
    assert_same_result(ours.result, cli)
    prepared = saltus.WhatIf(M2)
    assert prepared.tuck["found"]
    low, high = prepared.tuck["tuck_later_range_s"]
    assert low < 0 < high
    again = prepared.fly(tuck_later=0.03, tuck_scale=1.1)
    assert again.result == ours.result
    assert len(again.times) == len(again.somersault_tilt_twist)
    with pytest.raises(saltus.InputError):
        prepared.fly(tuck_later=high + 1.0)
    with pytest.raises(saltus.InputError):
        saltus.what_if(M1, tuck_later=0.05)  # M1 has no tuck


def test_import_capture_is_saltus_import(tmp_path):
    ours = saltus.import_capture(BACKFLIP_BVH, keyframes=6)
    cli = cli_result("import", BACKFLIP_BVH, "--keyframes", 6, "--out", tmp_path / "cli")
    assert_same_result(ours.result, cli)
    assert len(ours.keyframes.keyframes) == 6
    ours.write(tmp_path / "py")
    for name in ("keyframes.motion.json", "capture.motion.json", "trajectory.csv"):
        assert filecmp.cmp(tmp_path / "cli" / name, tmp_path / "py" / name, shallow=False), name
    with pytest.raises(saltus.InputError, match="keyframes"):
        saltus.import_capture(BACKFLIP_BVH, keyframes=1)
    with pytest.raises(saltus.InputError, match="flight"):
        saltus.import_capture(BACKFLIP_BVH, flight=(1.0, 0.5))


def test_export_by_format_name_is_saltus_export(tmp_path):
    formats = {f["name"]: f for f in saltus.export_formats()}
    assert {"bvh", "html"} <= set(formats)
    run_cli("export", M1, "--format", "bvh", "--fps", 30, "--out", tmp_path / "cli.bvh", "-q")
    summary = saltus.export(M1, tmp_path / "py.bvh", format="bvh", fps=30)
    assert filecmp.cmp(tmp_path / "cli.bvh", tmp_path / "py.bvh", shallow=False)
    assert summary["format"] == "bvh" and summary["frames"] == round(2.04 * 30) + 1
    # A motion in memory exports as its file does.
    saltus.export(saltus.read_motion(M1), tmp_path / "memory.bvh", format="bvh", fps=30)
    assert filecmp.cmp(tmp_path / "cli.bvh", tmp_path / "memory.bvh", shallow=False)
    saltus.export(M1, tmp_path / "m1.html", format="html")
    assert (tmp_path / "m1.html").read_text().lstrip().lower().startswith("<!doctype html>")
    # Every other format of the table, by its name alone, as the CLI writes it.
    for name, f in formats.items():
        if name in ("bvh", "html"):
            continue
        out = "x" + f["extension"]
        run_cli("export", M1, "--format", name, "--out", tmp_path / "cli" / out, "-q")
        written = saltus.export(M1, tmp_path / "py" / out, format=name)
        assert written["files"], name
    with pytest.raises(saltus.InputError, match="format"):
        saltus.export(M1, tmp_path / "x", format="obj")


def test_models_are_saltus_model_new_scale_yeadon_and_info(tmp_path):
    run_cli("model", "new", "--height", 1.62, "--mass", 55, "--sex", "female", "--out",
            tmp_path / "cli.model.json", "-q")
    saltus.model_new(1.62, 55, "female").write(tmp_path / "py.model.json")
    assert filecmp.cmp(tmp_path / "cli.model.json", tmp_path / "py.model.json", shallow=False)
    run_cli("model", "scale", "zatsiorsky-66kg", "--height", 1.8, "--mass", 80, "--name", "big",
            "--out", tmp_path / "cli-big.model.json", "-q")
    saltus.model_scale("zatsiorsky-66kg", 1.8, 80, name="big").write(tmp_path / "big.model.json")
    assert filecmp.cmp(tmp_path / "cli-big.model.json", tmp_path / "big.model.json",
                       shallow=False)
    run_cli("model", "yeadon", YEADON_MALE, "--out", tmp_path / "cli-y.model.json", "-q")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        saltus.model_yeadon(YEADON_MALE).write(tmp_path / "y.model.json")
    assert filecmp.cmp(tmp_path / "cli-y.model.json", tmp_path / "y.model.json", shallow=False)
    info = json.loads(run_cli("model", "info", "zatsiorsky-66kg", "--json").stdout)
    assert saltus.model_info("zatsiorsky-66kg") == info
    assert saltus.model_info(saltus.read_model("zatsiorsky-66kg")) == info
    with pytest.raises(saltus.InputError) as raised:
        saltus.model_new(17.0, 55, "female")  # centimetres for metres
    assert raised.value.file == "height"
    with pytest.raises(saltus.InputError, match="sex"):
        saltus.model_new(1.6, 55, "other")
    run_cli("model", "new", "--height", 1.62, "--mass", 55, "--sex", "female", "--age", 40,
            "--strength", "elite-gymnast", "--out", tmp_path / "cli-40.model.json", "-q")
    saltus.model_new(1.62, 55, "female", age=40, strength="elite-gymnast").write(
        tmp_path / "py-40.model.json")
    assert filecmp.cmp(tmp_path / "cli-40.model.json", tmp_path / "py-40.model.json",
                       shallow=False)
    with pytest.raises(saltus.InputError, match="age"):
        saltus.model_new(1.6, 55, "female", age=300)


def test_a_result_folder_of_the_cli_reads_back(m1_quick):
    ours, cli, cli_dir = m1_quick
    folder = saltus.read_result(cli_dir)
    assert folder.result["after"] == cli["after"]
    assert folder.after is not None
    assert (folder.after.root_force == ours.after.root_force).all()
    with pytest.raises(saltus.InputError):
        saltus.read_result(cli_dir / "missing")


def table_without_seconds(folder):
    """athletes.csv without its `seconds` column (how long each case took)."""
    rows = list(csv.reader(open(folder / "athletes.csv")))
    drop = rows[0].index("seconds")
    return [row[:drop] + row[drop + 1:] for row in rows]


def test_study_athletes_and_merge_are_the_cli_s(tmp_path):
    junior = tmp_path / "junior.model.json"
    saltus.model_new(1.45, 38, "female", name="junior").write(junior)
    short = ["--knots-per-interval", 1, "--max-iter", 20, "--joint-load-weight", 0]
    run_cli("study", "athletes", M1, "--models", junior, *short, "--jobs", 1,
            "--out", tmp_path / "cli", "-q")
    lines = []
    ours = saltus.study_athletes(M1, [str(junior)], tmp_path / "py", jobs=1,
                                 knots_per_interval=1, max_iter=20, joint_load_weight=0,
                                 progress=lines.append)
    assert ours["complete"] and ours["failed"] == 0 and ours["cases_run"] == 2
    assert len(lines) == 2
    assert table_without_seconds(tmp_path / "cli") == table_without_seconds(tmp_path / "py")
    # Shards merged give the folder one run gives.
    for i in (1, 2):
        saltus.study_athletes(M1, [str(junior)], tmp_path / f"shard{i}", jobs=1,
                              shard=f"{i}/2", knots_per_interval=1, max_iter=20,
                              joint_load_weight=0)
    saltus.study_merge([tmp_path / "shard1", tmp_path / "shard2"], tmp_path / "merged")
    assert table_without_seconds(tmp_path / "merged") == table_without_seconds(tmp_path / "py")


def test_study_mass_is_the_cli_s(tmp_path):
    run_cli("study", "mass", M1, "--max-iter", 15, "--out", tmp_path / "cli", "-q")
    ours = saltus.study_mass(M1, tmp_path / "py", max_iter=15)
    cli = json.loads((tmp_path / "cli" / "result.json").read_text())
    assert_same_result(ours, cli)
    for name in ("mass.csv", "model_scaled.json"):
        assert filecmp.cmp(tmp_path / "cli" / name, tmp_path / "py" / name, shallow=False), name


def test_the_studies_check_their_arguments_as_the_cli_does(tmp_path):
    junior = str(tmp_path / "junior.model.json")
    saltus.model_new(1.45, 38, "female", name="junior").write(junior)
    with pytest.raises(saltus.InputError, match="tail"):
        saltus.study_convergence([M1], tmp_path / "c", mass_segments=["tail"])
    with pytest.raises(saltus.InputError):
        saltus.study_athletes(M1, ["no-such-athlete"], tmp_path / "a")
    with pytest.raises(saltus.InputError, match="max_iter"):
        saltus.study_athletes(M1, ["zatsiorsky-66kg"], tmp_path / "a", max_iter=-2)
    with pytest.raises(saltus.InputError, match="shard"):
        saltus.study_athletes(M1, [junior], tmp_path / "a", shard="3/2")
    assert not (tmp_path / "a").exists() and not (tmp_path / "c").exists()
