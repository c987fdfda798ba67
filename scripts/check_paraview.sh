#!/usr/bin/env bash
# scripts/check_paraview.sh OUT_DIR/CASE.pvd
# Opens a run's .pvd series in ParaView's own Python (pvpython, Debian package python3-paraview)
# and prints, per block of the last frame, its point count and arrays. Not part of CI.
#
# On Debian 12 python3-paraview conflicts with python3-vtk9, which libvtk9-dev (needed to build
# grainload) depends on: installing one removes the other. So when pvpython is missing this
# script installs ParaView, runs the check, and then puts the build packages back (removing
# ParaView again) with scripts/ensure_packages.sh, whatever the check's outcome.
set -euo pipefail
if [[ $# -ne 1 ]]; then
  echo "usage: scripts/check_paraview.sh OUT_DIR/CASE.pvd" >&2
  exit 2
fi
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
sudo_cmd=()
[[ $(id -u) -ne 0 ]] && sudo_cmd=(sudo)
if ! command -v pvpython >/dev/null 2>&1; then
  echo "check_paraview: installing python3-paraview (replaces libvtk9-dev until the end)" >&2
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq python3-paraview
  restore_build_packages() {
    DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get remove -y -qq python3-paraview paraview
    bash "$root/scripts/ensure_packages.sh"
  }
  trap restore_build_packages EXIT
fi
pvd="$(realpath "$1")"
PVD="$pvd" pvpython --force-offscreen-rendering - <<'PY'
import os
from paraview import simple, servermanager
reader = simple.PVDReader(FileName=os.environ["PVD"])
times = list(reader.TimestepValues)
print(f"{os.environ['PVD']}: {len(times)} frames, t = {times[0]} .. {times[-1]} s")
reader.UpdatePipeline(times[-1])
data = servermanager.Fetch(reader)
for index in range(data.GetNumberOfBlocks()):
    block = data.GetBlock(index)
    name = data.GetMetaData(index).Get(data.NAME())
    arrays = [block.GetPointData().GetArrayName(i)
              for i in range(block.GetPointData().GetNumberOfArrays())]
    print(f"  block {name}: {block.GetNumberOfPoints()} points, arrays {', '.join(arrays)}")
    if block.GetNumberOfPoints() == 0:
        raise SystemExit("empty block")
PY
