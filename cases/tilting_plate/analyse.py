#!/usr/bin/python3
"""Onset of sliding on the tilting plate, from a run's frames.

Usage: /usr/bin/python3 cases/tilting_plate/analyse.py OUT [--spacing MM]

The plate's angle at each frame is read from its wall particles (block "wall_plate"): the
direction of its first layer. The body is the frame's one particle block that is not a wall
(the block, or the heap of tilting_plate_cone_moist_small.toml). The body's slip is its centroid's displacement along the plate,
measured in the plate's frame (hinge at the origin). Onset: the first frame at which the slip
speed along the plate exceeds 1 mm/s (a rigid block sliding from rest at the friction angle
reaches that speed 0.3 deg later at 5 deg/s). Prints angle, slip and slip speed per frame.
"""
import glob
import math
import sys

import numpy as np
from vtk import vtkXMLMultiBlockDataReader
from vtk.util.numpy_support import vtk_to_numpy


def blocks(vtm):
    reader = vtkXMLMultiBlockDataReader()
    reader.SetFileName(vtm)
    reader.Update()
    out = reader.GetOutput()
    named = {}
    for k in range(out.GetNumberOfBlocks()):
        name = out.GetMetaData(k).Get(out.NAME())
        named[name] = vtk_to_numpy(out.GetBlock(k).GetPoints().GetData())
    return named


def main():
    out = sys.argv[1]
    frames = sorted(glob.glob(out + "/frames/*.vtm"))
    times = [float(l.split('timestep="')[1].split('"')[0])
             for l in open(glob.glob(out + "/*.pvd")[0]) if 'timestep="' in l]
    rows = []
    for t, vtm in zip(times, frames):
        b = blocks(vtm)
        plate = b["wall_plate"]
        # The plate turns rigidly about the origin: the angle of its farthest particle.
        far = plate[np.argmax(np.linalg.norm(plate[:, :2], axis=1))]
        far0 = rows[0][4] if rows else far
        angle = math.atan2(far[1], far[0]) - math.atan2(far0[1], far0[0])
        along = np.array([math.cos(angle), math.sin(angle)])
        body = next(name for name in b if not name.startswith("wall_"))
        centroid = b[body][:, :2].mean(axis=0)
        rows.append((t, angle, float(centroid @ along), 0.0, far))
    print("time_s  plate_deg  slip_mm  slip_speed_mm_s")
    onset = None
    for k, (t, angle, s, _, _) in enumerate(rows):
        speed = 0.0 if k == 0 else (s - rows[k - 1][2]) / (t - rows[k - 1][0])
        slip = s - rows[0][2]
        print(f"{t:.3f} {math.degrees(angle):9.3f} {1e3 * slip:9.4f} {1e3 * speed:9.3f}")
        if onset is None and -speed > 1e-3:
            onset = math.degrees(angle)
    print(f"onset_angle_deg {onset}")


if __name__ == "__main__":
    main()
