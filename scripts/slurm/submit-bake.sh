#!/bin/bash
# Submits a pvscope bake as a Slurm job array of N shards and a merge that runs when they succeed.
#   submit-bake.sh [--resume] N ZONE OUT [bake options: --method raster --points 64 ...]
# The parts, their reports and the logs go to OUT.parts/ (on a file system every node sees).
# Prints the array's job id and the merge's, one per line (the array's is empty when --resume
# found every part). --resume keeps the parts already written and submits only the missing
# shards: after a task failed or was cancelled (the merge is then cancelled with it, as its
# dependency can no longer be met), run the same command again with --resume. Without it, earlier
# parts are removed first. Extra sbatch options (partition, account, time limit) go in SBATCH_*
# environment variables, which sbatch reads itself (SBATCH_PARTITION=..., SBATCH_TIMELIMIT=...).
set -euo pipefail
resume=0
if [ "${1:-}" = --resume ]; then
  resume=1
  shift
fi
if [ $# -lt 3 ]; then
  sed -n '2,11p' "$0" >&2
  exit 2
fi
n=$1
zone=$(realpath "$2")
out=$(realpath -m "$3")
shift 3
here=$(dirname "$(realpath "$0")")
parts="$out.parts"
mkdir -p "$parts"
[ "$resume" = 1 ] || rm -f "$parts"/part-*.pvsp
missing=()
for ((k = 0; k < n; k++)); do
  [ -f "$parts/part-$k.pvsp" ] || missing+=("$k")
done
array=""
dependency=()
if [ ${#missing[@]} -gt 0 ]; then
  indices=$(IFS=,; echo "${missing[*]}")
  array=$(sbatch --parsable --chdir="$parts" --array="$indices" "$here/bake-shard.sbatch" "$zone" "$parts" "$n" "$@")
  array=${array%%;*}
  dependency=(--dependency=afterok:"$array" --kill-on-invalid-dep=yes)
fi
merge=$(sbatch --parsable --chdir="$parts" "${dependency[@]}" "$here/merge.sbatch" "$zone" "$parts" "$out")
echo "$array"
echo "${merge%%;*}"
