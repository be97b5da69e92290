#!/usr/bin/env bash
# Every Freedoom map through walk (40 cameras, exact popping with portal-full baked on the spot) and
# an inspector screenshot under Xvfb: a line per map, then the failure count (docs/doom.md).
# Usage: tests/bench/tools/doom_every_map_check.sh BUILD_DIR
set -u
build=${1:?usage: doom_every_map_check.sh BUILD_DIR}
P="$build/app/pvscope"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail=0; n=0
for wad in freedoom1 freedoom2; do
  src=/usr/share/games/doom/$wad.wad; gwa=$work/$wad.gwa
  glbsp -q -xp $src -o $gwa > /dev/null 2>&1
  maps=$($P info $src --gwa $gwa | sed -n 's/.*maps in the WAD (--map NAME): //p')
  for m in $maps; do
    n=$((n+1))
    out=$($P walk $src --gwa $gwa --map $m --cameras 40 --pvs portal-full 2>&1) || { echo "WALK FAIL $wad $m"; fail=$((fail+1)); }
    pop=$(echo "$out" | grep -i "popping" | head -1)
    xvfb-run -a -s "-screen 0 640x480x24" $P inspect $src --gwa $gwa --map $m --screenshot $work/shot.png --frames 2 --size 640x480 > /dev/null 2>&1 || { echo "INSPECT FAIL $wad $m"; fail=$((fail+1)); }
    echo "$wad $m: $pop"
  done
done
echo "maps $n failures $fail"
