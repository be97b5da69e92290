#!/usr/bin/env bash
# Smoke run of every fuzz target (CI, after ctest): builds tests/fuzz with clang (PVSCOPE_FUZZ,
# ASan + UBSan + libFuzzer) in its own build folder, makes the seed corpora
# (make-corpora.sh), then runs each target for PVSCOPE_FUZZ_RUNS executions (default 20 000;
# PVSCOPE_FUZZ_SECONDS, default 30, caps a slow target's time) on its seeds and dictionary.
# Every target runs; the smoke fails at the end when any had a finding (a crash, a sanitizer
# report, a timeout of 10 s per input, running out of memory at 2 GB, a target that cannot
# start) or had no seed to start from (an empty corpus tests almost nothing). Crash inputs are
# kept in BUILD/fuzz-artifacts/<target>/; new inputs the run finds go to a scratch folder, so
# the corpora stay as made.
# The smoke guards against regressions, it does not explore: every run starts from the same
# random seed, so a given build mutates the same inputs in the same order and CI does not turn
# red on a finding a lucky seed stumbles on (that is the long runs' job, run-long.sh). A fixed
# number of executions makes every run go equally far along that sequence, on any machine
# (unless the time cap stops a slow target first).
#   PVSCOPE_FUZZ_BUILD_DIR  build folder (default build-fuzz)
#   PVSCOPE_FUZZ_RUNS       executions per target (default 20000)
#   PVSCOPE_FUZZ_SECONDS    at most this many seconds per target (default 30)
#   PVSCOPE_FUZZ_TARGETS    targets to run (default: all, from the build's targets.txt)
#   PVSCOPE_FUZZ_SEED       libFuzzer's -seed (default 1; 0 lets libFuzzer pick one)
#   PVSCOPE_JOBS            build jobs (default: nproc)
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
cd "$root"
build=${PVSCOPE_FUZZ_BUILD_DIR:-build-fuzz}
seconds=${PVSCOPE_FUZZ_SECONDS:-30}
runs=${PVSCOPE_FUZZ_RUNS:-20000}
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
    seeds=$(ls "$corpus" | wc -l)
    if [ "$seeds" -eq 0 ]; then
        echo "run-smoke: $target has no seeds in $corpus (make-corpora.sh)" >&2
        failed+=("$target")
        continue
    fi
    echo "run-smoke: $target, $runs runs (at most ${seconds}s) on $seeds seeds"
    if ! "$build/tests/fuzz/$target" -runs="$runs" -max_total_time="$seconds" -seed="$seed" -timeout=10 -rss_limit_mb=2048 \
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
    echo "run-smoke: findings (or no seeds) in ${failed[*]}" >&2
    exit 1
fi
echo "run-smoke: every target ran without a finding"
