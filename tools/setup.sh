#!/usr/bin/env bash
# Installs the Debian packages Crumple builds, tests and runs with (skips what is present).
set -euo pipefail
packages=(build-essential cmake ninja-build g++ libgtest-dev libgmock-dev libbenchmark-dev
          libomp-dev libcli11-dev libfmt-dev nlohmann-json3-dev libssl-dev
          libopenmpi-dev openmpi-bin libmetis-dev python3 python3-vtk9 python3-numpy python3-matplotlib clang-format
          clang libclang-rt-dev chromium)
# clang and libclang-rt-dev (on Debian 12 it pulls libclang-rt-14-dev, which holds
# libclang_rt.fuzzer): the fuzz preset's libFuzzer build of the deck reader. chromium: the
# test that `crumple report`'s page renders in a real browser with its pictures.
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq "${missing[@]}"
fi
