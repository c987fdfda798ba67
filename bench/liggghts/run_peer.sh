#!/usr/bin/env bash
# LIGGGHTS peer for bench/dem_throughput: the same spheres settling in the same box, timed the
# same way (settle steps untimed, then the timed steps), on R MPI ranks (LIGGGHTS' parallelism;
# grainload's is threads). Prints LIGGGHTS' own loop time of the timed run and grain-steps/s.
#
# Usage: bench/liggghts/run_peer.sh [--ranks R] [--grains N] [--settle S] [--steps S]
#        (default 2 ranks, 5000 grains, 40 000 settle steps, 10 000 timed steps, step 5 us)
# Installs the Debian package liggghts (3.8) with apt-get if it is missing.
set -euo pipefail

ranks=2 grains=5000 settle=40000 steps=10000
while (($# > 0)); do
  case "$1" in
    --ranks) ranks=$2 ;;
    --grains) grains=$2 ;;
    --settle) settle=$2 ;;
    --steps) steps=$2 ;;
    *) echo "run_peer.sh: unknown option $1" >&2; exit 2 ;;
  esac
  shift 2
done

if ! command -v liggghts >/dev/null; then
  sudo_cmd=()
  if [[ $(id -u) -ne 0 ]]; then sudo_cmd=(sudo); fi
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends \
    liggghts openmpi-bin >&2
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# The fill region's height keeps the solid fraction at 0.25, as bench/dem_throughput.cpp's.
height=$(python3 -c "import math; print($grains * 4/3 * math.pi * 0.0025**3 / 0.25 / 0.01)")
sed -e "s/@GRAINS@/$grains/; s/@HEIGHT@/$height/; s/@SETTLE@/$settle/; s/@STEPS@/$steps/" \
  "$(dirname "$0")/settling.in" > "$work/in.settling"
(cd "$work" && mpirun --allow-run-as-root --oversubscribe -np "$ranks" liggghts -in in.settling \
  > log.txt 2>&1) || { tail -20 "$work/log.txt" >&2; exit 1; }
# "Loop time of T on P procs for S steps with N atoms, finish time ...": the timed run's.
loop=$(grep "^Loop time of" "$work/log.txt" | tail -1)
seconds=$(echo "$loop" | sed -E 's/^Loop time of ([0-9.eE+-]+) .*/\1/')
atoms=$(echo "$loop" | sed -E 's/.* with ([0-9]+) atoms.*/\1/')
echo "liggghts: $atoms grains, $ranks ranks, $settle settle + $steps timed steps of 5e-06 s"
python3 -c "print('  wall %.3f s  %.4g grain-steps/s' % ($seconds, $atoms * $steps / $seconds))"
