#!/usr/bin/env bash
# The sharded bake against the one-machine bake on every format pvscope writes: for each zone, the
# raster bake (METHOD=reference: the per-source reference at 32 lines a region) whole, then as
# N = 1, 2, 7 and 16 shards merged (the shards one after the other on
# this machine); prints one line per zone and N with the merged file's first bytes of SHA-256 and
# "same" or "DIFFERENT". Exit 1 when any file differs.
#   tests/bench/tools/shard_identity.sh BUILD_DIR [SHARED_DATA_DIR]
set -euo pipefail
pvscope=$(realpath "$1/app/pvscope")
shared=$(realpath "${2:-$(dirname "$0")/../../../../shared/data}")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
raster=(--method raster --resolution 8 --points 2 --threads 2)
if [ "${METHOD:-raster}" = reference ]; then
  raster=(--method reference --samples 32 --per-source --threads 2)
fi
different=0

check() { # NAME ZONE EXT [zone options]
  local name=$1 zone=$2 ext=$3
  shift 3
  mkdir -p "$name/whole"
  "$pvscope" bake "$zone" "$@" "${raster[@]}" -o "$name/whole/out.$ext" 2> /dev/null
  local whole
  whole=$(sha256sum < "$name/whole/out.$ext" | cut -c1-16)
  for n in 1 2 7 16; do
    mkdir -p "$name/n$n/merged"
    for ((k = 0; k < n; k++)); do
      "$pvscope" bake "$zone" "$@" "${raster[@]}" --shard "$k/$n" -o "$name/n$n/part-$k.pvsp" 2> /dev/null
    done
    "$pvscope" merge "$name/n$n"/part-*.pvsp --zone "$zone" -o "$name/n$n/merged/out.$ext" 2> /dev/null
    local merged verdict=same
    merged=$(sha256sum < "$name/n$n/merged/out.$ext" | cut -c1-16)
    [ "$merged" = "$whole" ] || { verdict=DIFFERENT; different=1; }
    printf '%-22s N=%-3s %s %s\n' "$name" "$n" "$merged" "$verdict"
  done
}

"$pvscope" gen --rooms 40 --seed 1 -o gen.s3d > /dev/null 2>&1
check "generated .s3d" gen.s3d s3d
check "e1m1 (BSP 29)" "$shared/quake/e1m1.bsp" bsp
check "lqdm2 (BSP2)" "$shared/modern-quake/q1/lqdm2-bsp2.bsp" bsp
check "lqdm2 (2PSB)" "$shared/modern-quake/q1/lqdm2-2psb.bsp" bsp
check "lqdm2 (Quake 2 IBSP)" "$shared/modern-quake/q2/lqdm2-q2.bsp" bsp
[ "${METHOD:-raster}" = reference ] || check "E1M1.obj (.hepvs)" "$shared/hateengine/E1M1.obj" hepvs --cell 16 --grid-size 16
if [ -f /usr/share/games/doom/freedoom2.wad ] && command -v glbsp > /dev/null; then
  cp /usr/share/games/doom/freedoom2.wad fd2.wad
  glbsp -q fd2.wad -o fd2.gwa > /dev/null 2>&1
  check "freedoom2 MAP01 (.gwa)" fd2.wad gwa --map MAP01
fi
exit $different
