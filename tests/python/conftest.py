"""Fixtures of the Python module's tests (tests/python/README.md): the module, the real `saltus`
program to compare it with, the bundled motions, and results both make once per session."""

import json
import os
import subprocess
from pathlib import Path

import pytest

import saltus

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "examples"
M1 = str(EXAMPLES / "motions" / "M1-straight-back-somersault.motion.json")
M7 = str(EXAMPLES / "motions" / "M7-double-front-one-and-a-half-twists.motion.json")
ARMS = str(EXAMPLES / "motions" / "full-twisting-back-somersault-from-the-arms.motion.json")
M2 = str(EXAMPLES / "motions" / "M2-tucked-back-somersault.motion.json")
BACKFLIP_BVH = str(EXAMPLES / "captures" / "deepmimic-backflip.bvh")
YEADON_MALE = str(EXAMPLES / "athletes" / "yeadon-male1.txt")

# Keys of result.json that say how long a run took: the only ones two runs may differ in.
TIMING_KEYS = {"solve_seconds"}


def cli_path():
    path = os.environ.get("SALTUS_CLI")
    if not path:
        pytest.fail("SALTUS_CLI is not set (CTest sets it to the saltus program)")
    return path


def run_cli(*args, expect=0):
    """Runs `saltus ARGS`; returns the finished process (stdout and stderr as text). `expect`:
    the exit status it must end with (None: any)."""
    done = subprocess.run([cli_path(), *map(str, args)], capture_output=True, text=True)
    if expect is not None:
        assert done.returncode == expect, (args, done.returncode, done.stderr)
    return done


def cli_result(*args):
    """Runs a verb of `saltus` into a new folder (its --out) and returns that folder's
    result.json; the folder is the last argument."""
    run_cli(*args, "-q")
    return json.loads((Path(args[-1]) / "result.json").read_text())


def without_timing(value):
    if isinstance(value, dict):
        return {k: without_timing(v) for k, v in value.items() if k not in TIMING_KEYS}
    if isinstance(value, list):
        return [without_timing(v) for v in value]
    return value


def assert_same_result(ours, cli):
    """The same result.json: every key and every number as the file holds it (the module's
    numbers pass through the same JSON writer, so equal means equal to the last digit)."""
    assert without_timing(ours) == without_timing(cli)


@pytest.fixture(scope="session")
def m1_optimised(tmp_path_factory):
    """M1 optimised with the defaults by the module and by the CLI, once per session."""
    out = tmp_path_factory.mktemp("m1") / "cli"
    cli = cli_result("optimize", M1, "--out", out)
    return saltus.optimize(M1), cli, out


# A short optimisation (knots at the keyframes, 20 iterations, no joint-load polish): where a
# test needs an optimised motion or folder, not the default run's figures.
QUICK = dict(knots_per_interval=1, max_iter=20, joint_load_weight=0.0)
QUICK_FLAGS = ["--knots-per-interval", 1, "--max-iter", 20, "--joint-load-weight", 0]


@pytest.fixture(scope="session")
def m1_quick(tmp_path_factory):
    """M1 optimised briefly (QUICK) by the module and by the CLI, once per session."""
    out = tmp_path_factory.mktemp("m1-quick") / "cli"
    done = run_cli("optimize", M1, *QUICK_FLAGS, "--out", out, "-q", expect=None)
    assert done.returncode in (0, 3), done.stderr
    return saltus.optimize(M1, **QUICK), json.loads((out / "result.json").read_text()), out
