#!/usr/bin/env bash
# scripts/test.sh [ctest options]
# Installs missing Debian packages, builds Release (incrementally), and runs the test suite
# (labels unit, verification, regression). Long validation runs: scripts/test.sh -L validation
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$root/scripts/build.sh"
if [[ $# -eq 0 ]]; then
  set -- -LE validation
fi
cd "${GRAINLOAD_BUILD:-$root/build}"
exec ctest --output-on-failure -j "${GRAINLOAD_JOBS:-$(nproc)}" "$@"
