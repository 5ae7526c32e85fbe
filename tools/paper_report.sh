#!/usr/bin/env bash
# The paper's experiments reproduced in one command: `saltus paper` (Table 1, the mass and
# convergence studies, report.md) followed by the desktop app's figure export into OUT/figures
# (Figs. 4-5, 8, 9), which report.md links to.
#
#   bash tools/paper_report.sh OUT [--quick] [other `saltus paper` options]
#
# Uses the binaries in build/release/bin (or $SALTUS_BIN). Without a display the figures are
# drawn under xvfb-run. Without saltus-gui (built with -DSALTUS_BUILD_GUI=OFF) the report is
# written without figures.
set -euo pipefail

if [ $# -lt 1 ]; then
  echo "usage: bash tools/paper_report.sh OUT [--quick] [saltus paper options]" >&2
  exit 2
fi
out="$1"
shift
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bin="${SALTUS_BIN:-$root/build/release/bin}"

"$bin/saltus" paper "$root/examples/motions" --out "$out" "$@"

# A shard or a Slurm script is not the report yet: its figures come after `saltus study merge`.
for arg in "$@"; do
  case "$arg" in
    --shard|--shard=*|--emit-slurm|--emit-slurm=*)
      echo "no figures yet: merge the shards (saltus study merge), then saltus-gui --export-figures REPORT/figures REPORT/M1 ..." >&2
      exit 0 ;;
  esac
done

if [ ! -x "$bin/saltus-gui" ]; then
  echo "saltus-gui not built: $out/report.md has no figures" >&2
  exit 0
fi
folders=()
for d in "$out"/M[0-9]* "$out"/dive* "$out"/mass; do
  [ -d "$d" ] && folders+=("$d")
done
display=()
if [ -z "${DISPLAY:-}" ]; then display=(xvfb-run -a -s "-screen 0 1920x1200x24"); fi
"${display[@]}" "$bin/saltus-gui" --export-figures "$out/figures" "${folders[@]}"
echo "wrote $out/report.md and $out/figures/"
