#!/usr/bin/env bash
# Every map of Freedoom's two IWADs baked with the 2-D portal vis, one `pvscope bake` per map,
# as a markdown table (docs/performance.md "Doom: 2-D portal vis"): subsectors, portals, mean
# visible, wall time, peak RSS. GL nodes by glbsp (a .gwa per WAD, made here).
# Usage: tests/bench/tools/doom_vis_batch.sh BUILD_DIR [METHOD] [THREADS]
set -euo pipefail
build=${1:?usage: doom_vis_batch.sh BUILD_DIR [METHOD] [THREADS]}
method=${2:-portal-full}
threads=${3:-2}
pvscope="$build/app/pvscope"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "| WAD | map | subsectors | portals | mean visible | ${method} s | peak RSS MB |"
echo "|---|---|---:|---:|---:|---:|---:|"
total=0
for wad in freedoom1 freedoom2; do
  src=/usr/share/games/doom/$wad.wad
  glbsp -q -xp "$src" -o "$work/$wad.gwa" > /dev/null 2>&1
  maps=$("$pvscope" info "$src" --gwa "$work/$wad.gwa" | sed -n 's/.*maps in the WAD (--map NAME): //p')
  for map in $maps; do
    "$pvscope" bake "$src" --gwa "$work/$wad.gwa" --map "$map" --method "$method" --threads "$threads" \
      -o "$work/out.gwa" --report "$work/r.json" 2> "$work/err.txt" > /dev/null
    python3 - "$wad" "$map" "$work/r.json" "$work/err.txt" <<'PY'
import json, re, sys
wad, name, report, err = sys.argv[1:]
r = json.load(open(report))
m = re.search(r"(\d+) portals", open(err).read())
print(f"| {wad} | {name} | {r['regions']} | {m.group(1) if m else '?'} | {r['mean_visible']:.1f} | "
      f"{r['time_seconds']:.2f} | {r['peak_rss_bytes'] / 1048576:.0f} |")
PY
  done
done
