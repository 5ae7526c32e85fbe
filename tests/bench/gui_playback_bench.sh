#!/bin/sh
# The app's 3D view while playing M7 (the double front with 1½ twists) with software OpenGL
# (Mesa's llvmpipe under Xvfb), at a laptop's 1366x768 and at 1920x1080: the frames per second
# shown and the process's CPU time per frame (every thread: llvmpipe rasterises on threads of
# its own), which other work on the machine disturbs less than the frame rate. Target: at least
# 30 frames per second at 1366x768 (docs/performance.md, "The 3D view while playing").
#
#   tests/bench/gui_playback_bench.sh [BUILD_DIR] [SECONDS] [RUNS]
set -eu
build=${1:-build/release}
seconds=${2:-5}
runs=${3:-3}
here=$(cd "$(dirname "$0")/../.." && pwd)
motion="$here/examples/motions/M7-double-front-one-and-a-half-twists.motion.json"
for run in $(seq "$runs"); do
  for size in 1366x768 1920x1080; do
    LIBGL_ALWAYS_SOFTWARE=1 xvfb-run -a -s "-screen 0 1920x1080x24" \
      "$build/bin/saltus-gui" "$motion" --size "$size" --benchmark-playback --seconds "$seconds" \
      2>/dev/null | sed "s/^/run $run: /"
  done
done
