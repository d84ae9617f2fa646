#!/usr/bin/env bash
# Installs the Debian 12 packages Soak needs, only those missing. Idempotent.
# Needs root (or sudo). The CUDA toolkit is not a Debian package: if
# /usr/local/cuda (or nvcc on PATH) is there, the CUDA backend is built too.
# clang and its runtime are for the sanitizer build and the fuzzers (Doc/reliability.md);
# pybind11, numpy and pytest for the Python module, venv and pip for its `pip install .` test
# (Doc/python.md), OpenVDB (whose CMake module also asks for Boost.Iostreams) for the .vdb
# export (Doc/output.md); Blender for the tests of the Blender add-on (Demos/blender,
# Doc/output.md "Blender"); Slurm and munge for the test that runs `soak sweep` on a
# one-node Slurm (Doc/sweeps.md); ParaView's Catalyst (paraview-dev, python3-paraview) with
# Python's headers (python3-dev) for the Catalyst adaptor, Xvfb for its pictures in the tests
# (Doc/paraview.md, "In situ and live").
set -euo pipefail
packages=(
  build-essential cmake ninja-build pkg-config
  libeigen3-dev libpugixml-dev libgtest-dev libtinyobjloader-dev
  paraview-dev python3-paraview python3-dev
  xvfb python3-matplotlib
  pybind11-dev python3-pybind11 python3-numpy python3-pytest python3-venv python3-pip libopenvdb-dev libboost-iostreams-dev
  clang libclang-rt-14-dev libomp-dev
  blender
  slurmctld slurmd slurm-client munge
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi
echo "install-deps: installing ${missing[*]}"
sudo=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "install-deps: run as root or install sudo" >&2; exit 1; }
  sudo=sudo
fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
