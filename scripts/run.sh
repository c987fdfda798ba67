#!/usr/bin/env bash
# scripts/run.sh CASE.toml [grainload run options]
# Installs missing Debian packages, builds Release (incrementally), and runs the case.
set -euo pipefail
if [[ $# -lt 1 ]]; then
  echo "usage: scripts/run.sh CASE.toml [--out DIR] [--threads N] [--set key=value ...]" >&2
  exit 2
fi
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$root/scripts/build.sh" --target grainload
exec "${GRAINLOAD_BUILD:-$root/build}/app/grainload" run "$@"
