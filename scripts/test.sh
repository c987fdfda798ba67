#!/usr/bin/env bash
# scripts/test.sh [ctest options]
# Installs missing Debian packages, builds Release (incrementally), and runs the test suite
# (labels unit, verification, regression). The long validation runs (label validation: the
# full cases of docs/validation/ against their references, each alone, 30-45 min in all):
#   scripts/test.sh -L validation                    all of them
#   scripts/test.sh -L validation -R SiloRest        one of them (docs/validation.md lists them)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$root/scripts/build.sh"
if [[ $# -eq 0 ]]; then
  set -- -LE validation
fi
cd "${GRAINLOAD_BUILD:-$root/build}"
exec ctest --output-on-failure -j "${GRAINLOAD_JOBS:-$(nproc)}" "$@"
