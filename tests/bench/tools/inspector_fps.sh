#!/usr/bin/env bash
# The inspector's frame rate where users look: e1m1 from its player start and the default outdoor
# zone over seeded cameras, each with the default overlays and with every overlay, in a 1280x720
# window under Xvfb (Mesa's llvmpipe), Release. The runs alternate, REPS times, so a busy moment
# of the machine falls on every configuration alike; each prints the inspector's own
# `--report-fps` summary (the frame's median and p95, and where the frame goes).
# Usage: tests/bench/tools/inspector_fps.sh BUILD_DIR [REPS] [CAMERAS]
set -euo pipefail
build=${1:?usage: inspector_fps.sh BUILD_DIR [REPS] [CAMERAS]}
reps=${2:-2}
cameras=${3:-300}
root=$(cd "$(dirname "$0")/../../.." && pwd)
shared=${PVSCOPE_SHARED_DATA_DIR:-$root/../shared/data}
pvscope="$(cd "$build" && pwd)/app/pvscope"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

"$pvscope" gen --outdoor -o "$work/outdoor.s3d" > /dev/null
every=membership,membership-boxes,planes,portals,bounds,zonelines,frustum
run() { # run LABEL ARGS...
  local label=$1
  shift
  echo "== $label"
  xvfb-run -a -s "-screen 0 1400x900x24" "$pvscope" inspect "$@" --size 1280x720 --report-fps | sed 's/^/   /'
}
for rep in $(seq "$reps"); do
  echo "# repetition $rep"
  run "e1m1, default overlays" "$shared/quake/e1m1.bsp" --frames 300
  run "e1m1, every overlay" "$shared/quake/e1m1.bsp" --frames 300 --overlays "$every"
  run "outdoor, default overlays, $cameras cameras" "$work/outdoor.s3d" --cameras "$cameras"
  run "outdoor, every overlay, $cameras cameras" "$work/outdoor.s3d" --cameras "$cameras" --overlays "$every"
done
