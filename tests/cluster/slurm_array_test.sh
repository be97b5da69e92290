#!/bin/bash
# A sharded bake on a real Slurm: starts a one-node cluster on localhost in a temporary folder
# (scripts/slurm/local-cluster.sh: Debian's munged, slurmctld and slurmd, no cgroups, no
# accounting), submits
# scripts/slurm/submit-bake.sh's job array and merge for a generated zone and, when the shared data
# is there, for e1m1, waits for them, and checks each merged file against the one-machine bake,
# byte for byte. Every daemon it started is stopped by pid on the way out, whatever happened.
#   slurm_array_test.sh PVSCOPE [SHARED_DATA_DIR]
# Exit 0 passed, 1 failed, 77 skipped (no Slurm or munge installed, or not root: slurmd must be).
# With PVSCOPE_REQUIRE_SHARED_DATA=1 (CI) a skip or missing shared data is a failure.
set -euo pipefail
skip() {
  if [ "${PVSCOPE_REQUIRE_SHARED_DATA:-0}" = 1 ]; then
    echo "FAIL: $* (PVSCOPE_REQUIRE_SHARED_DATA=1)"
    exit 1
  fi
  echo "SKIP: $*"
  exit 77
}
pvscope=$(realpath "$1")
shared=${2:-}
repo=$(cd "$(dirname "$0")/../.." && pwd)

for tool in munged slurmctld slurmd sbatch squeue sinfo; do
  if ! command -v "$tool" >/dev/null && [ ! -x "/usr/sbin/$tool" ]; then
    skip "$tool is not installed (Debian: slurmctld slurmd slurm-client munge; setup-debian.sh installs them)"
  fi
done
if [ "$(id -u)" -ne 0 ]; then
  skip "slurmd runs jobs as their users and must be started as root"
fi
export PATH="$PATH:/usr/sbin"

# Slurm keeps socket and state paths short (at most about 64 characters): a folder under /tmp.
tmp=$(mktemp -d /tmp/pvsl.XXXXXX)
stop_all() {
  "$repo/scripts/slurm/local-cluster.sh" stop "$tmp" || true
  rm -rf "$tmp"
}
trap stop_all EXIT
fail() {
  echo "FAIL: $*"
  for log in "$tmp"/*.log "$tmp"/*/*.log; do [ -f "$log" ] && { echo "--- $log"; tail -20 "$log"; }; done
  exit 1
}
"$repo/scripts/slurm/local-cluster.sh" start "$tmp" || fail "the one-node Slurm did not start"
# shellcheck disable=SC1091
source "$tmp/env"

# Waits for a job (and, for an array, all its tasks) to leave the queue.
wait_job() {
  for _ in $(seq 1500); do
    [ -z "$(squeue -h -j "$1" 2>/dev/null)" ] && return 0
    sleep 0.2
  done
  fail "job $1 still queued after 300 s"
}

# Waits for the job ids submit-bake.sh printed (array, merge).
wait_submission() {
  local array merge
  array=$(echo "$1" | sed -n 1p)
  merge=$(echo "$1" | sed -n 2p)
  [ -z "$array" ] || wait_job "$array"
  wait_job "$merge"
}

# Bakes ZONE on one machine, then as N shards on Slurm, and compares the files. With FAULT=1 one
# task is cancelled first (held, cancelled, the rest released): the merge must not run, and
# submit-bake.sh --resume must bake the missing shard and merge.
check_zone() {
  local zone=$1 ext=$2 n=$3
  shift 3
  local name ids
  name=$(basename "$zone" ."$ext")
  mkdir -p "$tmp/$name/one" "$tmp/$name/slurm"
  local one="$tmp/$name/one/$name.$ext" merged="$tmp/$name/slurm/$name.$ext"
  "$pvscope" bake "$zone" "$@" --threads 2 -o "$one" 2> "$tmp/$name/one.log" || fail "the one-machine bake of $zone"
  if [ "${FAULT:-0}" = 1 ]; then
    ids=$(SBATCH_HOLD=1 PVSCOPE="$pvscope" "$repo/scripts/slurm/submit-bake.sh" "$n" "$zone" "$merged" "$@") ||
      fail "submit-bake.sh $zone (held)"
    local array merge
    array=$(echo "$ids" | sed -n 1p)
    merge=$(echo "$ids" | sed -n 2p)
    scancel "${array}_1"
    scontrol release "$array" "$merge"
    wait_submission "$ids"
    [ ! -e "$merged" ] || fail "$name: the merge ran although shard 1 was cancelled"
    [ ! -e "$merged.parts/part-1.pvsp" ] || fail "$name: the cancelled shard left a part"
    echo "ok: $name: shard 1 cancelled, the merge did not run; resubmitting the missing shard"
    ids=$(PVSCOPE="$pvscope" "$repo/scripts/slurm/submit-bake.sh" --resume "$n" "$zone" "$merged" "$@") ||
      fail "submit-bake.sh --resume $zone"
  else
    ids=$(PVSCOPE="$pvscope" "$repo/scripts/slurm/submit-bake.sh" "$n" "$zone" "$merged" "$@") ||
      fail "submit-bake.sh $zone"
  fi
  wait_submission "$ids"
  [ -f "$merged" ] || fail "$name: the merge wrote nothing (jobs $(echo $ids))"
  cmp "$one" "$merged" || fail "$name: the merged file differs from the one-machine bake"
  local parts
  parts=$(ls "$merged.parts"/part-*.pvsp | wc -l)
  [ "$parts" -eq "$n" ] || fail "$name: $parts parts, not $n"
  echo "ok: $name: $n shards on Slurm (jobs $(echo $ids)) merged to the one-machine bake's bytes ($(sha256sum < "$merged" | cut -c1-16))"
}

"$pvscope" gen --rooms 30 --seed 4 -o "$tmp/generated.s3d" > /dev/null 2>&1 || fail "gen"
FAULT=1 check_zone "$tmp/generated.s3d" s3d 3 --method raster --resolution 8 --points 2
if [ -n "$shared" ] && [ -f "$shared/quake/e1m1.bsp" ]; then
  cp "$shared/quake/e1m1.bsp" "$tmp/e1m1.bsp"
  check_zone "$tmp/e1m1.bsp" bsp 4 --method raster --resolution 8 --points 1
elif [ "${PVSCOPE_REQUIRE_SHARED_DATA:-0}" = 1 ]; then
  fail "no shared data at '${shared}' (PVSCOPE_REQUIRE_SHARED_DATA=1)"
else
  echo "SKIP (part): no shared data at '${shared}': e1m1 not baked on Slurm"
fi
echo "PASS"
