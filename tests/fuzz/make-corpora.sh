#!/usr/bin/env bash
# Seed corpora for the fuzz targets, made under a build folder (never in git):
#   tests/fuzz/make-corpora.sh BUILD_DIR [OUT]      (OUT defaults to BUILD_DIR/corpora)
# BUILD_DIR is a PVSCOPE_FUZZ build holding tests/fuzz/fuzz_make_seeds. Sources:
#  - pvscope's own zones: generated levels (5 and 12 rooms, baked) written as .s3d, .wld,
#    .obj + .hepvs, .prt, and codec / edit-list seeds from their PVS (fuzz_make_seeds gen);
#  - the real files in ../shared/data when present (Quake maps as they are and converted to
#    .s3d / .obj, the visdemo .prt, HateEngine's E1M1 .obj and .hepvs);
#  - Freedoom (Debian's freedoom package) with GL nodes made by glbsp (V2, V3, V5 .gwa) and
#    zdbsp (V2, V5 in the WAD): a few maps each as small PWADs, and a textures WAD;
#  - the small hand-written seeds in tests/fuzz/seeds/<target>/.
# Missing sources are skipped with a message (the generated zones are always there), except
# under PVSCOPE_REQUIRE_SHARED_DATA=1 (CI), where a missing source fails: the targets whose
# seeds come only from it would otherwise run on empty corpora.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
require=${PVSCOPE_REQUIRE_SHARED_DATA:-0}
missing() { # missing MESSAGE: skip a source, or fail when sources are required
    if [ "$require" = 1 ]; then
        echo "make-corpora: $1 (PVSCOPE_REQUIRE_SHARED_DATA=1: failing)" >&2
        exit 1
    fi
    echo "make-corpora: $1"
}
build=${1:?usage: make-corpora.sh BUILD_DIR [OUT]}
out=${2:-$build/corpora}
seeds=$build/tests/fuzz/fuzz_make_seeds
shared=${PVSCOPE_SHARED_DATA_DIR:-$root/../shared/data}
doom=${PVSCOPE_FREEDOOM_DIR:-/usr/share/games/doom}
[ -x "$seeds" ] || { echo "make-corpora: $seeds missing (build the fuzz targets first)" >&2; exit 1; }

rm -rf "$out"
mkdir -p "$out"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
copy() { # copy TARGET FILE...: real files into a target's corpus
    local target=$1; shift
    mkdir -p "$out/$target"
    cp "$@" "$out/$target/"
}

"$seeds" gen "$out"

if [ -d "$shared" ]; then
    "$seeds" bsp "$out" "$shared/visdemo/example.bsp" "$shared/visdemo/example.prt"
    "$seeds" bsp "$out" "$shared/quake/end.bsp"
    copy bsp29 "$shared/quake/e1m1.bsp"
    # BSP2 and 2PSB (the same level as lqdm2.bsp, as ericw's qbsp -bsp2 / -2psb wrote it), vised
    # by ericw: PVS, ambient levels and every wide record.
    for f in lqdm2-bsp2.ericw-vis.bsp lqdm2-2psb.ericw-vis.bsp lqdm2.ericw-vis.bsp; do
        [ -f "$shared/modern-quake/q1/$f" ] && copy bsp29 "$shared/modern-quake/q1/$f"
    done
    # Quake 2 maps from ericw's qbsp -q2bsp, unvised and vised (PVS and PHS rows).
    for f in "$shared"/modern-quake/q2/*.bsp; do
        [ -f "$f" ] && copy ibsp38 "$f"
    done
    copy obj "$shared/hateengine/E1M1.obj"
    copy hepvs "$shared/hateengine/E1M1.hepvs"
else
    missing "$shared absent: no Quake or HateEngine seeds"
fi

iwad=$doom/freedoom1.wad
[ -f "$iwad" ] || iwad=$shared/visdemo/freedoom1.wad
if [ -f "$iwad" ] && command -v glbsp >/dev/null && command -v zdbsp >/dev/null; then
    "$seeds" doom "$out" "$iwad" - 0 # the textures WAD (and no map: 0 maps)
    # GL nodes for two small maps alone (a PWAD each: the builders would do all 36 otherwise).
    for map in E1M1 E1M8; do
        "$seeds" extract "$iwad" $map "$tmp/$map.wad"
        for v in 2 3 5; do
            glbsp -q -xp -v$v "$tmp/$map.wad" -o "$tmp/${map}_glbsp_v$v.gwa" >/dev/null 2>&1
            "$seeds" doom "$out" "$tmp/$map.wad" "$tmp/${map}_glbsp_v$v.gwa" 1
        done
        zdbsp -t -g -o "$tmp/${map}_zdbsp_v2.wad" "$tmp/$map.wad" >/dev/null 2>&1
        zdbsp -t -g -5 -o "$tmp/${map}_zdbsp_v5.wad" "$tmp/$map.wad" >/dev/null 2>&1
        for w in zdbsp_v2 zdbsp_v5; do
            "$seeds" doom "$out" "$tmp/${map}_$w.wad" - 1
        done
    done
else
    missing "Freedoom, glbsp or zdbsp missing: no Doom seeds"
fi

for dir in "$root"/tests/fuzz/seeds/*/; do
    [ -d "$dir" ] && copy "$(basename "$dir")" "$dir"*
done
for dir in "$out"/*/; do
    echo "make-corpora: $(basename "$dir"): $(ls "$dir" | wc -l) seeds, $(du -sh "$dir" | cut -f1)"
done
