#!/usr/bin/env bash
# Smoke run of every fuzz target (CI, after ctest): builds tests/fuzz with clang (PVSCOPE_FUZZ,
# ASan + UBSan + libFuzzer) in its own build folder, makes the seed corpora
# (make-corpora.sh), then runs each target for PVSCOPE_FUZZ_SECONDS (default 20) on its seeds
# and dictionary. Fails on the first finding: a crash, a sanitizer report, a timeout (10 s per
# input), running out of memory (2 GB), or a target that cannot start. Crash inputs are kept in
# BUILD/fuzz-artifacts/<target>/; new inputs the run finds go to a scratch folder, so the
# corpora stay as made.
# The smoke guards against regressions, it does not explore: every run starts from the same
# random seed, so a given build mutates the same inputs in the same order and CI does not turn
# red on a finding a lucky seed stumbles on (that is the long runs' job, run-long.sh). Only the
# time limit varies how far along that sequence a run gets.
#   PVSCOPE_FUZZ_BUILD_DIR  build folder (default build-fuzz)
#   PVSCOPE_FUZZ_SECONDS    seconds per target (default 20)
#   PVSCOPE_FUZZ_TARGETS    targets to run (default: all, from the build's targets.txt)
#   PVSCOPE_FUZZ_SEED       libFuzzer's -seed (default 1; 0 lets libFuzzer pick one)
#   PVSCOPE_JOBS            build jobs (default: nproc)
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
cd "$root"
build=${PVSCOPE_FUZZ_BUILD_DIR:-build-fuzz}
seconds=${PVSCOPE_FUZZ_SECONDS:-20}
seed=${PVSCOPE_FUZZ_SEED:-1}
jobs=${PVSCOPE_JOBS:-$(nproc)}
start=$(date +%s)

CC=clang CXX=clang++ cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPVSCOPE_FUZZ=ON \
    -DPVSCOPE_WERROR=ON >/dev/null
cmake --build "$build" -j "$jobs"
built=$(date +%s)
tests/fuzz/make-corpora.sh "$build" "$build/corpora"

. tests/fuzz/target-options.sh

targets=${PVSCOPE_FUZZ_TARGETS:-$(cat "$build/tests/fuzz/targets.txt")}
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
failed=()
for target in $targets; do
    name=${target#fuzz_}
    corpus=$build/corpora/$name
    mkdir -p "$corpus" "$scratch/$name" "$build/fuzz-artifacts/$name"
    dict=$scratch/$name.dict
    fuzz_dict_file "$target" "$dict"
    dict_arg=()
    [ -s "$dict" ] && dict_arg=(-dict="$dict")
    echo "run-smoke: $target for ${seconds}s on $(ls "$corpus" | wc -l) seeds"
    if ! "$build/tests/fuzz/$target" -max_total_time="$seconds" -seed="$seed" -timeout=10 -rss_limit_mb=2048 \
            -max_len="$(fuzz_max_len_for "$target")" \
            -print_final_stats=1 "${dict_arg[@]}" -artifact_prefix="$build/fuzz-artifacts/$name/" \
            "$scratch/$name" "$corpus" >"$scratch/$name.log" 2>&1; then
        tail -60 "$scratch/$name.log"
        echo "run-smoke: $target FAILED (inputs in $build/fuzz-artifacts/$name/)" >&2
        failed+=("$target")
        continue
    fi
    grep -E '^stat::number_of_executed_units|cov:' "$scratch/$name.log" | tail -2 | tr '\n' ' '
    echo
done
end=$(date +%s)
echo "run-smoke: build $((built - start)) s, corpora and runs $((end - built)) s"
if [ ${#failed[@]} -gt 0 ]; then
    echo "run-smoke: findings in ${failed[*]}" >&2
    exit 1
fi
echo "run-smoke: every target ran without a finding"
