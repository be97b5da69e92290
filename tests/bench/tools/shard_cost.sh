#!/usr/bin/env bash
# What splitting a bake costs, measured in one run: the one-machine bake, then N shards one after
# the other (each on THREADS threads), then the merge. Prints wall and CPU seconds and peak RSS of
# each, the shards' CPU sum over the whole bake's CPU, the slowest shard over the mean (balance),
# and the merge's time and peak RSS against the rows' size (regions x rows / 8 bytes).
#   tests/bench/tools/shard_cost.sh BUILD_DIR ZONE EXT N [bake options: --method raster ...]
# Needs GNU time (/usr/bin/time, Debian package "time").
set -euo pipefail
pvscope=$(realpath "$1/app/pvscope")
zone=$(realpath "$2")
ext=$3
n=$4
shift 4
work=$(mktemp -d)
mkdir -p "$work/m"
trap 'rm -rf "$work"' EXIT
measure() { # OUT_FILE command...: "wall user+sys rss_kb" into OUT_FILE
  local out=$1
  shift
  /usr/bin/time -f "%e %U %S %M" -o "$out.t" "$@" 2> "$out.log" > /dev/null
  awk '{printf "%s %.2f %s\n", $1, $2 + $3, $4}' "$out.t" > "$out"
}
measure "$work/whole" "$pvscope" bake "$zone" "$@" -o "$work/whole.$ext"
for ((k = 0; k < n; k++)); do
  measure "$work/m/shard$k" "$pvscope" bake "$zone" "$@" --shard "$k/$n" -o "$work/part-$k.pvsp"
done
mkdir -p "$work/merged"
measure "$work/merge" "$pvscope" merge "$work"/part-*.pvsp --zone "$zone" -o "$work/merged/whole.$ext"
cmp -s "$work/whole.$ext" "$work/merged/whole.$ext" && same=yes || same=NO
read -r whole_wall whole_cpu whole_rss < "$work/whole"
cat "$work"/m/shard*[0-9] | awk -v n="$n" -v cpu="$whole_cpu" -v wall="$whole_wall" -v rss="$whole_rss" '
  { sum_cpu += $2; sum_wall += $1; if ($1 > max_wall) max_wall = $1; if ($3 > max_rss) max_rss = $3 }
  END {
    printf "whole bake:  %.2f s wall, %.2f CPU-s, %.1f MB peak\n", wall, cpu, rss / 1024
    printf "%d shards:   %.2f CPU-s in all (%.3fx the whole), slowest %.2f s wall (%.2fx the mean), %.1f MB peak at most\n",
           n, sum_cpu, sum_cpu / cpu, max_wall, max_wall / (sum_wall / n), max_rss / 1024
  }'
read -r merge_wall merge_cpu merge_rss < "$work/merge"
regions=$("$pvscope" info "$zone" --json 2> /dev/null | python3 -c 'import json,sys; print(json.load(sys.stdin)["counts"]["regions"])')
rows_mb=$(awk -v r="$regions" 'BEGIN { printf "%.1f", r * r / 8 / 1048576 }') # a zone with a grid: rows are its cells
echo "merge:       ${merge_wall} s wall, $(awk '{printf "%.1f", $3 / 1024}' "$work/merge") MB peak (the rows: ${rows_mb} MB); merged file identical: $same"
