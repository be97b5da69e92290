#!/usr/bin/env bash
# Long fuzz runs (docs/fuzzing.md records them): every target, or those named, for SECONDS each,
# two at a time, each on its own growing corpus BUILD/long-corpus/<name> plus the seeds in
# BUILD/corpora/<name> (make-corpora.sh), with its dictionary and max_len (target-options.sh); logs in BUILD/fuzz-logs/<name>.log,
# crash inputs in BUILD/fuzz-artifacts/<name>/. Build the targets first (run-smoke.sh does).
#   tests/fuzz/run-long.sh SECONDS [TARGET...]
# PVSCOPE_FUZZ_BUILD_DIR (default build-fuzz), PVSCOPE_FUZZ_PARALLEL (default 2),
# PVSCOPE_FUZZ_RUNS (also stop a target after this many executions: 10 M or an hour is the bar).
# Exits 1 when any target had a finding (listed at the end), 0 when none did.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
cd "$root"
seconds=${1:?usage: run-long.sh SECONDS [TARGET...]}
shift
build=${PVSCOPE_FUZZ_BUILD_DIR:-build-fuzz}
parallel=${PVSCOPE_FUZZ_PARALLEL:-2}
targets=${*:-$(cat "$build/tests/fuzz/targets.txt")}
. tests/fuzz/target-options.sh
mkdir -p "$build/fuzz-logs"
findings=$build/fuzz-logs/findings.txt
: >"$findings"

run_one() {
    local target=$1 name=${1#fuzz_}
    local corpus=$build/long-corpus/$name
    mkdir -p "$corpus" "$build/fuzz-logs" "$build/fuzz-artifacts/$name"
    local dict=$build/fuzz-logs/$name.dict
    fuzz_dict_file "$target" "$dict"
    local dict_arg=() runs_arg=()
    [ -n "${PVSCOPE_FUZZ_RUNS:-}" ] && runs_arg=(-runs="$PVSCOPE_FUZZ_RUNS")
    [ -s "$dict" ] && dict_arg=(-dict="$dict")
    nice -n 10 "$build/tests/fuzz/$target" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
        -max_len="$(fuzz_max_len_for "$target")" \
        -print_final_stats=1 "${dict_arg[@]}" "${runs_arg[@]}" -artifact_prefix="$build/fuzz-artifacts/$name/" \
        "$corpus" "$build/corpora/$name" \
        >"$build/fuzz-logs/$name.log" 2>&1 && echo "run-long: $target done" ||
        { echo "run-long: $target FINDING"; echo "$target" >>"$findings"; }
}

running=0
for target in $targets; do
    run_one "$target" &
    running=$((running + 1))
    if [ $running -ge "$parallel" ]; then
        wait -n || true
        running=$((running - 1))
    fi
done
wait
if [ -s "$findings" ]; then
    echo "run-long: findings in $(tr '\n' ' ' <"$findings")(logs in $build/fuzz-logs, inputs in $build/fuzz-artifacts)" >&2
    exit 1
fi
echo "run-long: every target ran without a finding"
