#!/usr/bin/env bash
# The lines a change touches follow .clang-format: git clang-format over the C++ lines that differ
# from BASE (default PVSCOPE_FORMAT_BASE, else HEAD~1: the change CI lands), untouched lines left
# as they are. Prints the fix as a diff and fails when there is one; says so and passes when
# clang-format or the history is missing. Usage: check_format.sh [BASE]
set -uo pipefail
cd "$(dirname "$0")/../.."
base=${1:-${PVSCOPE_FORMAT_BASE:-HEAD~1}}
if ! command -v git-clang-format > /dev/null || ! command -v clang-format > /dev/null; then
  echo "check_format: clang-format not installed (./setup-debian.sh installs it): not checked"
  exit 0
fi
if ! git rev-parse --verify --quiet "$base^{commit}" > /dev/null; then
  echo "check_format: no commit $base to compare with: not checked"
  exit 0
fi
diff=$(git clang-format --binary "$(command -v clang-format)" --diff --extensions h,cpp "$base" -- . 2>&1)
case "$diff" in
  "" | *"no modified files to format"* | *"did not modify any files"*)
    echo "check_format: the C++ lines changed since $base follow .clang-format"
    exit 0 ;;
esac
echo "check_format: lines changed since $base differ from .clang-format; the fix:"
echo "$diff"
exit 1
