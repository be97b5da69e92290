#!/usr/bin/env bash
# The SHA-256 of every file pvscope's bakes write from the project's test data, one line per bake:
# a refactoring that must not change behaviour compares this list before and after
# (`diff before.txt after.txt`). Covers `bake` with each portal method and clusters, `--prt` and
# `--write-prt`, `vis` in place (full, fast, --portals tree, --ambient-only) on Quake and Quake 2
# maps, the EverQuest, OBJ/.hepvs and Doom writers (GL_PVS, REJECT), the reference and raster on a
# small zone, and the terrain bake of a small outdoor zone.
# Usage: tests/bench/tools/bake_checksums.sh BUILD_DIR > checksums.txt
set -euo pipefail
build=${1:?usage: bake_checksums.sh BUILD_DIR}
root=$(cd "$(dirname "$0")/../../.." && pwd)
shared=${PVSCOPE_SHARED_DATA_DIR:-$root/../shared/data}
pvscope="$(cd "$build" && pwd)/app/pvscope"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"

sum() { # sum LABEL FILE...
  local label=$1
  shift
  echo "$label $(cat "$@" | sha256sum | cut -d' ' -f1)"
}
copy() { # copy SRC NAME: a writable copy in the work folder
  cp "$1" "$2"
  chmod u+w "$2"
}
run() { "$pvscope" "$@" > /dev/null 2>&1; }

for map in quake/e1m1 quake/e1m2 quake/e2m1 quake/dm2 quake/start quake/end visdemo/example; do
  name=$(basename $map)
  for method in portal-fast portal-full clustered; do
    run bake "$shared/$map.bsp" --method $method --threads 2 -o out.bsp
    sum "bake $map $method" out.bsp
  done
  run bake "$shared/$map.bsp" --method portal-full --sky none --level 2 --threads 2 -o out.bsp --write-prt out.prt
  sum "bake $map portal-full --sky none --level 2 --write-prt" out.bsp out.prt
  run bake "$shared/$map.bsp" --method portal-full --threads 2 --prt out.prt -o out.bsp
  sum "bake $map --prt" out.bsp
done
run bake "$shared/visdemo/example.bsp" --method portal-full --prt "$shared/visdemo/example.prt" -o out.bsp
sum "bake visdemo/example --prt example.prt" out.bsp

for map in modern-quake/q1/lqdm2 modern-quake/q1/lqdm2-bsp2 modern-quake/q1/lqdm2-2psb modern-quake/q1/lqdm5 \
  modern-quake/q1/lq_e2m2 modern-quake/q2/q2_liquids modern-quake/q2/q2_areaportals modern-quake/q2/q2_tjunc_matrix \
  modern-quake/q2/lqdm2-q2 modern-quake/q2/lqdm5-q2; do
  name=$(basename $map)
  for args in "" "--fast" "--level 2" "--noambientsky"; do
    copy "$shared/$map.bsp" "$name.bsp"
    copy "$shared/$map.prt" "$name.prt"
    run vis -threads 2 $args "$name.bsp"
    sum "vis $map $args" "$name.bsp"
  done
  copy "$shared/$map.bsp" "$name.bsp"
  run bake "$name.bsp" --prt "$shared/$map.prt" --threads 2 -o out.bsp
  sum "bake $map --prt" out.bsp
done
for map in modern-quake/q1/lqdm2 modern-quake/q2/lqdm2-q2; do
  name=$(basename $map)
  copy "$shared/$map.bsp" "$name.bsp"
  copy "$shared/$map.prt" "$name.prt"
  run vis -threads 2 --portals tree "$name.bsp"
  sum "vis $map --portals tree" "$name.bsp"
done
copy "$shared/modern-quake/q1/lqdm2.ericw-vis.bsp" lq.bsp
run vis --ambient-only lq.bsp
sum "vis --ambient-only lqdm2.ericw-vis" lq.bsp
copy "$shared/modern-quake/q2/lqdm2-q2.ericw-vis.bsp" q2.bsp
run vis -phsonly q2.bsp
sum "vis -phsonly lqdm2-q2.ericw-vis" q2.bsp

# EverQuest: a generated zone written as .s3d, baked back; OBJ + .hepvs; Doom.
run gen --rooms 40 --seed 3 --no-bake -o gen.s3d
for method in portal-fast portal-full clustered reference; do
  run bake gen.s3d --method $method --threads 2 --samples 64 -o out.s3d
  sum "bake gen.s3d $method" out.s3d
done
run bake gen.s3d --method portal-full --clusters auto --threads 2 -o out.s3d
sum "bake gen.s3d --clusters auto" out.s3d
run gen --outdoor --size 2048 --no-bake -o outdoor.s3d
run bake outdoor.s3d --method terrain --threads 2 -o out.s3d
sum "bake outdoor.s3d terrain" out.s3d
copy "$shared/hateengine/E1M1.obj" E1M1.obj
run bake E1M1.obj --method raster --points 2 --resolution 16 --threads 2 -o out.hepvs
sum "bake E1M1.obj raster" out.hepvs
run bake "$shared/quake/end.bsp" --method raster --points 2 --resolution 16 --threads 2 -o out.bsp
sum "bake end raster" out.bsp
if [ -f /usr/share/games/doom/freedoom2.wad ] && command -v glbsp > /dev/null; then
  cp /usr/share/games/doom/freedoom2.wad fd2.wad
  glbsp -q fd2.wad -o fd2.gwa > /dev/null 2>&1
  # glBSP stamps the build time into the GL marker: the same stamp before and after.
  perl -0777 -pi -e 's/TIME=[0-9: .-]{24}/TIME=2000-01-01 00:00:00.0000/g' fd2.gwa
  for m in MAP01 MAP10; do
    run bake fd2.wad --map $m --threads 2 -o out.gwa
    sum "bake freedoom2 $m" out.gwa
    run bake fd2.wad --map $m --heights --threads 2 -o out.gwa
    sum "bake freedoom2 $m --heights" out.gwa
    run bake fd2.wad --map $m --method portal-fast --threads 2 -o out.gwa
    sum "bake freedoom2 $m portal-fast" out.gwa
  done
  cp fd2.wad in.wad
  cp fd2.gwa in.gwa
  run bake in.wad --map MAP01 --in-place --reject --threads 2
  sum "bake freedoom2 MAP01 --in-place --reject" in.wad in.gwa
fi
