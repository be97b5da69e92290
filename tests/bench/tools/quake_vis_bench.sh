#!/usr/bin/env bash
# `pvscope vis` on Quake levels compiled by today's tools, as a markdown table (docs/quake-vis.md):
# per level, the vis over qbsp's portal file (PRT1/PRT2) and, as the same-run baseline of the
# per-leaf path, `--portals tree`: wall and CPU seconds, peak RSS, mean visible, and the leaves
# given an ambient level; the missing and excess bits of the written PVS against the sampled
# reference (`pvscope compare --methods file`, converged); and whether the map written at 1, 2 and
# 3 threads is the same file byte for byte. Each run works on a copy of the map (vis writes in
# place). The reference takes about two minutes per run on lqdm5 (2 threads).
# Usage: tests/bench/tools/quake_vis_bench.sh BUILD_DIR [THREADS] [MAP.bsp ...]
#   (default maps: the shared modern-quake levels, lqdm2 and lqdm5; each needs its .prt beside it)
set -euo pipefail
build=${1:?usage: quake_vis_bench.sh BUILD_DIR [THREADS] [MAP.bsp ...]}
threads=${2:-2}
shift $(( $# >= 2 ? 2 : 1 ))
root=$(cd "$(dirname "$0")/../../.." && pwd)
shared=${PVSCOPE_SHARED_DATA_DIR:-$root/../shared/data}
maps=("$@")
[ ${#maps[@]} -gt 0 ] || maps=("$shared/modern-quake/q1/lqdm2.bsp" "$shared/modern-quake/q1/lqdm5.bsp")
pvscope="$build/app/pvscope"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "| map | portals | wall s | CPU s | peak RSS MB | mean visible | missing | excess | same at 1/2/3 threads | leaves with ambient sound |"
echo "|---|---|---:|---:|---:|---:|---:|---:|---|---:|"
for map in "${maps[@]}"; do
  name=$(basename "$map" .bsp)
  for portals in file tree; do
    cp "$map" "$work/$name.bsp"
    cp "${map%.bsp}.prt" "$work/$name.prt"
    chmod u+w "$work/$name.bsp" "$work/$name.prt"
    /usr/bin/time -f "%e %U %S %M" -o "$work/time.txt" \
      "$pvscope" vis -threads "$threads" --portals "$portals" --report "$work/r.json" "$work/$name.bsp" \
      2> "$work/err.txt" > /dev/null
    same=yes
    for t in 1 2 3; do
      cp "$map" "$work/t$t.bsp"
      cp "${map%.bsp}.prt" "$work/t$t.prt"
      chmod u+w "$work/t$t.bsp" "$work/t$t.prt"
      "$pvscope" vis -threads "$t" --portals "$portals" "$work/t$t.bsp" 2> /dev/null > /dev/null
      cmp -s "$work/t1.bsp" "$work/t$t.bsp" || same=no
    done
    "$pvscope" compare "$work/$name.bsp" --methods file --cameras 0 --threads "$threads" \
      --json "$work/c.json" > /dev/null 2>&1
    python3 - "$name" "$portals" "$work/r.json" "$work/time.txt" "$work/err.txt" "$work/c.json" "$same" <<'PY'
import json, re, sys
name, portals, report, timing, err, compare, same = sys.argv[1:]
r = json.load(open(report))
c = json.load(open(compare))
wall, user, system, rss_kb = open(timing).read().split()
m = re.search(r"ambient sounds on (\d+) of (\d+) leaves", open(err).read())
sound = f"{m.group(1)} of {m.group(2)}" if m else "?"
file_row = next(m for m in c["methods"] if m["method"] == "file")
missing, excess = file_row["missing_bits"], file_row["excess_bits"]
label = "qbsp's .prt" if portals == "file" else "--portals tree"
print(f"| {name} | {label} | {float(wall):.2f} | {float(user) + float(system):.2f} | {int(rss_kb) / 1024:.0f} | "
      f"{r['mean_visible']:.1f} | {missing} | {excess} | {same} | {sound} |")
PY
  done
done
