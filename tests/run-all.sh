#!/usr/bin/env bash
# Checks the format of the lines the last commit changed (tests/tools/check_format.sh), builds
# pvscope with AddressSanitizer + UndefinedBehaviorSanitizer and -Werror, then runs
# every test (ctest), then a smoke run of every libFuzzer target (tests/fuzz/run-smoke.sh: clang,
# its own build folder, ~20 s a target; PVSCOPE_SKIP_FUZZ_SMOKE=1 leaves it out). Tests labelled
# "slow" run only with PVSCOPE_SLOW_TESTS=1 (or `ctest -L slow` in a build folder).
# This is the README's test command and what .ci/run calls.
# Tests that need ../shared/data skip with a message when it is absent; set
# PVSCOPE_REQUIRE_SHARED_DATA=1 to make its absence a failure (CI does).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${PVSCOPE_TEST_BUILD_DIR:-build-test}
# The lines the change touches follow .clang-format (seconds; before the build's half hour).
tests/tools/check_format.sh
jobs=${PVSCOPE_JOBS:-$(nproc)}
# -g1 (line tables only): sanitizer reports still name file and line, and the build takes about a
# third less time than with full debug information.
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPVSCOPE_SANITIZE=ON -DPVSCOPE_WERROR=ON \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG" -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG"
cmake --build "$build" -j "$jobs"
ctest --test-dir "$build" --output-on-failure -j "$jobs" -LE slow
# Tests labelled "slow" (the converged reference within every conservative method, on every
# shared level: minutes even in Release, several times that under the sanitizers) run when asked.
if [ "${PVSCOPE_SLOW_TESTS:-0}" = 1 ]; then
  ctest --test-dir "$build" --output-on-failure -L slow
fi
if [ "${PVSCOPE_SKIP_FUZZ_SMOKE:-0}" != 1 ]; then
  PVSCOPE_JOBS=$jobs tests/fuzz/run-smoke.sh
fi
