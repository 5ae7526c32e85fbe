"""Speed of the Python module (docs/python.md, "Speed"); a script, not a test:

    SALTUS_CLI=build/release/bin/saltus PYTHONPATH=build/release/python \\
        /usr/bin/python3 tests/bench/python_module_bench.py [--rounds N] [--motions M1 M7]

1. optimize from Python against the `saltus` program on the same motions, interleaved (CLI,
   Python, CLI, Python, ...) so that a machine shared with other work slows both alike. Each
   side's time is the run's own, from reading the motion to the written folder: the CLI's
   "wrote ... in X s" line, and in Python the wall time of read_motion + optimize + write in
   one process that imported the module once. The ratio of the medians is the cost of calling
   from Python.
2. Converting a 2001-sample evaluation to numpy: every array of the result, first access (the
   arrays are made then and kept), best of many fresh evaluations.
"""

import argparse
import os
import re
import statistics
import subprocess
import tempfile
import time
from pathlib import Path

import saltus

ROOT = Path(__file__).resolve().parents[2]
MOTIONS = {p.name.split("-")[0]: p for p in (ROOT / "examples" / "motions").glob("*.motion.json")}
ARRAYS = ("times", "root_force", "root_moment", "residual_force", "residual_moment", "com",
          "com_velocity", "angular_momentum", "segment_positions", "segment_rotations",
          "joint_forces", "joint_moments", "strength_shares", "somersault_tilt_twist")


def cli_seconds(cli, motion, out):
    done = subprocess.run([cli, "optimize", str(motion), "--out", str(out)], check=False,
                          capture_output=True, text=True)
    assert done.returncode in (0, 3), done.stderr
    return float(re.search(r"\} in ([0-9.]+) s", done.stdout).group(1))


def python_seconds(motion, out):
    start = time.perf_counter()
    saltus.optimize(saltus.read_motion(str(motion))).write(out)
    return time.perf_counter() - start


def optimize_against_cli(cli, names, rounds):
    print("optimize: CLI against Python, interleaved, %d rounds each" % rounds)
    with tempfile.TemporaryDirectory() as tmp:
        for name in names:
            motion = MOTIONS[name]
            cli_times, python_times = [], []
            for _ in range(rounds):
                cli_times.append(cli_seconds(cli, motion, Path(tmp) / "cli"))
                python_times.append(python_seconds(motion, Path(tmp) / "py"))
            c, p = statistics.median(cli_times), statistics.median(python_times)
            print(f"  {name}: CLI median {c:.3f} s {sorted(round(t, 3) for t in cli_times)}, "
                  f"Python median {p:.3f} s {sorted(round(t, 3) for t in python_times)}: "
                  f"Python/CLI {p / c:.3f}")


def conversion(samples, repeats):
    motion = saltus.read_motion(str(MOTIONS["M1"]))
    best = float("inf")
    for _ in range(repeats):
        e = saltus.evaluate(motion, samples=samples)
        start = time.perf_counter()
        for name in ARRAYS:
            getattr(e, name)
        best = min(best, time.perf_counter() - start)
    shapes = ", ".join(f"{n} {getattr(e, n).shape}" for n in ARRAYS)
    print(f"numpy: every array of a {samples}-sample evaluation in {best * 1e3:.3f} ms "
          f"(best of {repeats})\n  {shapes}")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--rounds", type=int, default=5)
    parser.add_argument("--motions", nargs="*", default=["M1", "M7"])
    parser.add_argument("--skip-optimize", action="store_true")
    args = parser.parse_args()
    conversion(2001, 50)
    if not args.skip_optimize:
        optimize_against_cli(os.environ["SALTUS_CLI"], args.motions, args.rounds)


if __name__ == "__main__":
    main()
