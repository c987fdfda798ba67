#!/usr/bin/env bash
# scripts/check_paraview.sh OUT_DIR/CASE.pvd
# Opens a run's .pvd series in ParaView's own Python (pvpython, Debian package python3-paraview)
# and prints, per block of the last frame, its point count and arrays. Not part of CI: the
# package is large. Installs python3-paraview if missing.
set -euo pipefail
if [[ $# -ne 1 ]]; then
  echo "usage: scripts/check_paraview.sh OUT_DIR/CASE.pvd" >&2
  exit 2
fi
if ! dpkg -s python3-paraview >/dev/null 2>&1; then
  sudo_cmd=()
  [[ $(id -u) -ne 0 ]] && sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq python3-paraview
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
