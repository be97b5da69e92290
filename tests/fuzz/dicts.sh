# Sourced by run-smoke.sh and run-long.sh: the dictionaries (tests/fuzz/dict/) of each target,
# joined into one file, since libFuzzer takes a single -dict.
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
