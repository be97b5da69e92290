#!/usr/bin/env bash
# Installs the Debian 12 packages pvscope builds against, and only those that are missing.
# Run as root (or through sudo). Safe to run again: it does nothing when all are present.
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  libglm-dev zlib1g-dev nlohmann-json3-dev libcli11-dev libtbb-dev libstb-dev
  libgtest-dev libgmock-dev libbenchmark-dev libgmp-dev
  libirrlicht-dev libglfw3-dev libimgui-dev libsquish-dev libtinyobjloader-dev libembree-dev
  libcairo2-dev
  libgl-dev xvfb xauth libgl1-mesa-dri
  # The raster baker's GPU path (visibility/raster/gl_headless.h): EGL's headers, and Mesa's EGL
  # with llvmpipe, the software GPU its tests run on.
  libegl-dev libegl1 libegl-mesa0
  freedoom glbsp zdbsp
  # The fuzz smoke (tests/fuzz/run-smoke.sh): clang 14 and its compiler-rt, which holds
  # libFuzzer (libclang_rt.fuzzer-x86_64.a) and is only a recommendation of clang-14.
  clang libclang-rt-14-dev
  # The sharded bake's test on a one-node Slurm (tests/cluster/slurm_array_test.sh).
  slurmctld slurmd slurm-client munge
  # The format check of changed lines (tests/tools/check_format.sh, .clang-format).
  clang-format
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup-debian: all ${#packages[@]} packages are installed."
  exit 0
fi

sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "setup-debian: run as root or install sudo" >&2; exit 1; }
  sudo_cmd=(sudo)
fi
echo "setup-debian: installing ${missing[*]}"
"${sudo_cmd[@]}" apt-get update -qq
DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
echo "setup-debian: done."
