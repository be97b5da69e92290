# Sourced by run-smoke.sh and run-long.sh: the libFuzzer options of each target.
#
# Dictionaries (tests/fuzz/dict/): joined into one file per target, since libFuzzer takes a
# single -dict.
fuzz_dicts_for() {
    case $1 in
        fuzz_eq_zone) echo pfs wld dds bmp ;;
        fuzz_doom_map) echo doom ;;
        fuzz_roundtrip) echo bsp29 doom pfs wld prt hepvs ;;
        fuzz_gl_pvs) ;;
        *) echo "${1#fuzz_}" ;;
    esac
}

# fuzz_dict_file TARGET FILE: writes the target's joined dictionary (empty when it has none).
fuzz_dict_file() {
    : >"$2"
    local d
    for d in $(fuzz_dicts_for "$1"); do cat "tests/fuzz/dict/$d.dict" >>"$2"; done
}

# The largest input libFuzzer makes (-max_len; longer seeds are cut to it). Without one it is
# the largest seed: the real levels (e1m1.bsp 1.3 MB, E1M1.obj 0.8 MB) then make every
# mutation parse a megabyte, at 10 executions a second instead of hundreds. The smaller seeds
# (example.bsp, the generated zones, the Doom maps) fit; the big ones still seed, cut short.
fuzz_max_len_for() {
    case $1 in
        fuzz_obj | fuzz_wld) echo 65536 ;;
        fuzz_bsp29 | fuzz_ibsp38 | fuzz_doom_textures | fuzz_hepvs) echo 131072 ;;
        # A WAD's directory is at its end: a cut WAD is garbage, so every Doom seed must fit.
        fuzz_doom_map | fuzz_roundtrip) echo 262144 ;;
        *) echo 0 ;; # the largest seed
    esac
}
