#!/usr/bin/env bash
# Installs the Debian 12 packages grainload needs to build and test, only those missing.
# Sourced by scripts/run.sh and scripts/test.sh; safe to run on its own.
set -euo pipefail

GRAINLOAD_PACKAGES=(
  build-essential cmake pkg-config git
  libeigen3-dev libsuitesparse-dev libmetis-dev libopenblas-dev
  libvtk9-dev libgtest-dev libtomlplusplus-dev
  # Meshing of .geo geometry scripts (io/gmsh_runner); python3 runs the case scripts that
  # tests call (cases/hopper_wagon/export_k.py).
  gmsh python3
  # Plots: `grainload trade` draws error against wall time with scripts/plot_trade.py; the
  # case scripts, scripts/plot_wall_map.py and scripts/docs_pictures.py draw with matplotlib
  # on numpy arrays.
  python3-matplotlib python3-numpy
  # Case scripts read frames with VTK's Python bindings (cases/hopper_wagon/*.py), and
  # scripts/render_frames.py renders them to PNG off screen, under xvfb-run without a display
  # (tests/regression/test_render_frames.cpp does so in the test suite).
  python3-vtk9 xvfb xauth
)

missing=()
for package in "${GRAINLOAD_PACKAGES[@]}"; do
  if ! dpkg -s "$package" >/dev/null 2>&1; then
    missing+=("$package")
  fi
done

if ((${#missing[@]} > 0)); then
  echo "grainload: installing missing Debian packages: ${missing[*]}" >&2
  sudo_cmd=()
  if [[ $(id -u) -ne 0 ]]; then
    sudo_cmd=(sudo)
  fi
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get update -qq
  "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
