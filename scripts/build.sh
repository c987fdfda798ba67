#!/usr/bin/env bash
# scripts/build.sh [cmake --build options]
# Installs missing Debian packages, configures build/ in Release once, builds incrementally, and
# measures the machine's throughput once (build/calibration.json).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${GRAINLOAD_BUILD:-$root/build}"
bash "$root/scripts/ensure_packages.sh"
if [[ ! -f "$build/CMakeCache.txt" ]]; then
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
fi
cmake --build "$build" -j "${GRAINLOAD_JOBS:-$(nproc)}" "$@"
# Once per build directory: the throughput `grainload check` estimates run times with
# (bench/sph_throughput --calibrate, about half a minute; docs/user-guide/trade.md).
if [[ ! -f "$build/calibration.json" ]]; then
  cmake --build "$build" -j "${GRAINLOAD_JOBS:-$(nproc)}" --target calibration
fi
