#!/usr/bin/env bash
# scripts/build.sh [cmake --build options]
# Installs missing Debian packages, configures build/ in Release once, builds incrementally, and
# measures the machine's throughput (build/calibration.json) when the bench that measures it was
# rebuilt, i.e. after a change of the code it times.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${GRAINLOAD_BUILD:-$root/build}"
bash "$root/scripts/ensure_packages.sh"
if [[ ! -f "$build/CMakeCache.txt" ]]; then
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
fi
cmake --build "$build" -j "${GRAINLOAD_JOBS:-$(nproc)}" "$@"
# The throughput `grainload check` estimates run times with (bench/sph_throughput --calibrate,
# about a minute; docs/user-guide/trade.md): measured again whenever sph_throughput was
# relinked (bench/CMakeLists.txt), so that a faster or slower SPH step does not leave the
# estimates at the old code's speed; a no-op otherwise. It waits up to a minute for the machine
# to be quiet (the build just finished, others may still run) and records how busy it was.
cmake --build "$build" -j "${GRAINLOAD_JOBS:-$(nproc)}" --target calibration
