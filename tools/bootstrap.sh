#!/usr/bin/env bash
# One entry point for a fresh Debian 12 machine (run as root, or as a user with sudo):
#   bash tools/bootstrap.sh demo   installs what is missing, builds, runs the bundled example
#   bash tools/bootstrap.sh test   installs what is missing, builds, runs the full test suite
# .ci/run calls the "test" form, so CI and the README can never disagree.
set -euo pipefail

mode="${1:-demo}"
case "$mode" in demo|test) ;; *) echo "usage: bash tools/bootstrap.sh demo|test" >&2; exit 2 ;; esac

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"

# Debian packages the build and the tests need (see docs/dependencies.md).
packages=(build-essential cmake ninja-build pkg-config clang-format
          libeigen3-dev coinor-libipopt-dev libopenblas0-serial nlohmann-json3-dev libcli11-dev
          libgtest-dev libbenchmark-dev
          libvtk9-qt-dev libvtk9-dev qtbase5-dev xvfb xauth libgl1-mesa-dri ffmpeg libjs-three
          python3-dev pybind11-dev python3-numpy python3-matplotlib)
# The Python module (python/) is built in both forms; its tests and the notebook's run, and the
# MuJoCo export's check by MuJoCo itself, are the test form's.
# The test form also builds under AddressSanitizer and UndefinedBehaviorSanitizer with clang and
# runs the libFuzzer targets of the readers, import and export (llvm-symbolizer, from llvm, makes
# the reports readable).
# The cluster tests start a private Slurm on this machine and run a study through GNU parallel.
# The flight page's tests open it in headless Chromium and in Firefox ESR (on Xvfb, driven over
# WebDriver BiDi by a Python script with Debian's websocket client).
[ "$mode" = test ] && packages+=(clang libclang-rt-14-dev llvm slurm-wlm munge parallel chromium
                                 firefox-esr python3-websocket python3-pytest python3-nbclient
                                 python3-ipykernel jupyter-notebook libmujoco-dev nodejs)

# Each stage's wall time, so CI logs show where the time goes (CI's limit is 60 minutes).
stage_start=$SECONDS
stage() {
  echo "-- $((SECONDS - stage_start)) s (total $SECONDS s)"
  echo "== $*"
  stage_start=$SECONDS
}

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
# Debian's nodejs comes without npm (its own package); NodeSource's carries it and conflicts with
# Debian's npm, so npm is asked for only where the command is missing.
[ "$mode" = test ] && ! command -v npm >/dev/null && missing+=(npm)
if ((${#missing[@]})); then
  echo "== installing: ${missing[*]}"
  sudo_cmd=()
  if [ "$(id -u)" -ne 0 ]; then
    command -v sudo >/dev/null || { echo "need root (or sudo) to install: ${missing[*]}" >&2; exit 1; }
    sudo_cmd=(sudo)
  fi
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

if [ "$mode" = demo ]; then
  # The demo builds what it runs: the command line, the app and the Python module, not the tests.
  stage "configure and build saltus, saltus-gui and the Python module (Release)"
  cmake --preset release >/dev/null
  cmake --build --preset release -j"$(nproc)" --target saltus_cli saltus_gui saltus_python
  stage "the bundled motions: evaluate, simulate, optimise"
  motion=examples/motions/M1-straight-back-somersault.motion.json
  echo "== saltus evaluate $motion"
  build/release/bin/saltus evaluate "$motion" --out out/M1-evaluate
  echo "== saltus simulate $motion"
  build/release/bin/saltus simulate "$motion" --out out/M1-simulate
  # The main job: every bundled skill optimised (relaxed model, automatic resolution).
  for motion in examples/motions/*.motion.json; do
    name="$(basename "$motion" .motion.json)"
    echo "== saltus optimize $motion"
    build/release/bin/saltus optimize "$motion" --out "out/$name" 2>/dev/null
  done
  stage "where the twist comes from: a take-off twist (M7) and an aerial one (the arms)"
  for name in M7-double-front-one-and-a-half-twists full-twisting-back-somersault-from-the-arms; do
    echo "== saltus analyse twist examples/motions/$name.motion.json"
    build/release/bin/saltus analyse twist "examples/motions/$name.motion.json" --out "out/$name-twist"
  done
  stage "the same from Python (python/README.md)"
  PYTHONPATH=build/release/python /usr/bin/python3 -c 'import saltus
r = saltus.optimize("examples/motions/M1-straight-back-somersault.motion.json")
print("M1 from Python: average root force %.4g N -> %.4g N (%s)"
      % (r.before.average_root_force, r.after.average_root_force, r.status))'
  echo "-- $((SECONDS - stage_start)) s (total $SECONDS s)"
  exit 0
fi

# The glTF export's test runs Khronos's glTF validator, an npm package pinned by
# tests/support/npm/package-lock.json: npm ci installs exactly that version into
# tests/support/npm/node_modules (from npm's cache when it holds it, so a rerun needs no network).
stage "the glTF validator (npm ci in tests/support/npm)"
(cd tests/support/npm && npm ci --prefer-offline --no-audit --no-fund --loglevel=error)

stage "configure and build everything (Release)"
cmake --preset release >/dev/null
cmake --build --preset release -j"$(nproc)"

stage "format check (clang-format, .clang-format)"
mapfile -t sources < <(git ls-files '*.h' '*.cpp' 2>/dev/null || find src tests -name '*.h' -o -name '*.cpp')
clang-format --dry-run --Werror "${sources[@]}"

stage "tests"
ctest --preset release --output-on-failure --no-tests=error -j"$(nproc)"

# The same unit, integration and cli tests with clang under AddressSanitizer and
# UndefinedBehaviorSanitizer (float-cast-overflow included), and the libFuzzer targets of the
# readers, import and export for a short seeded run each (docs/safety.md). No GUI: it adds nothing the sanitizers look at.
stage "sanitizer build (clang, ASan + UBSan, libFuzzer targets)"
cmake --preset sanitize >/dev/null
cmake --build --preset sanitize -j"$(nproc)"
stage "sanitizer tests and fuzzing"
ctest --preset sanitize --output-on-failure --no-tests=error -j"$(nproc)"
echo "-- $((SECONDS - stage_start)) s (total $SECONDS s)"
