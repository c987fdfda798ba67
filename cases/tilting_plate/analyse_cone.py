#!/usr/bin/python3
"""Avalanche and sliding of the sand heap on the tilting plate, from a run's frames.

Usage: /usr/bin/python3 cases/tilting_plate/analyse_cone.py OUT

All positions are taken in the plate's frame (hinge at the origin, s along the plate, n
normal to it); the plate's angle theta is that of its wall particle farthest from the hinge,
as in analyse.py. Particle sets, chosen in the first frame:
- flank: the downhill flank's surface, the particle nearest the hinge in every row of the heap
  but the two bottom ones (the toe rests on the plate) and the top one;
- base: the bottom row's uphill half, away from where avalanching sand arrives.
Per frame it prints theta, the downhill flank's angle to the plate (least-squares slope of the
current outermost particle per row, rows of one spacing, bottom two and top rows left out)
and to the horizontal (+ theta), and the mean speed down the plate of the flank and the
median of the base, in the plate's frame. Events, once the plate has turned 0.5 deg (the
heap first settles onto the contact layer):
- first motion: the first frame at which the flank moves down the plate faster than 1 mm/s
  (a rigid body starting from rest at 5 deg/s reaches 1 mm/s 0.3 deg after its onset);
- flank failure: the frame at which the flank is steepest to the horizontal (before the
  slide): the largest angle it stands at, after which it collapses;
- flowing flank: its mean angle to the horizontal from 1 deg of turning after the failure to
  the slide, while sand runs down it;
- slide: the first frame at which the base moves down the plate faster than 1 mm/s.
"""
import glob
import math
import sys

import numpy as np
from vtk import vtkXMLMultiBlockDataReader
from vtk.util.numpy_support import vtk_to_numpy

THRESHOLD = 1e-3  # m/s
# Events are looked for once the plate has turned this far (degrees): before, the heap
# settles onto the plate's contact layer at a few mm/s.
START = 0.5


def blocks(vtm):
    reader = vtkXMLMultiBlockDataReader()
    reader.SetFileName(vtm)
    reader.Update()
    out = reader.GetOutput()
    return {out.GetMetaData(k).Get(out.NAME()):
            vtk_to_numpy(out.GetBlock(k).GetPoints().GetData())[:, :2]
            for k in range(out.GetNumberOfBlocks())}


def rows_of(points, spacing, bottom):
    """Row of every particle, counted in spacings from the first frame's bottom row `bottom`."""
    return np.round((points[:, 1] - bottom) / spacing).astype(int)


def outermost(points, spacing, bottom):
    """Index of the particle with the smallest s in every row, bottom two and top rows out."""
    rows = rows_of(points, spacing, bottom)
    return np.array([np.flatnonzero(rows == r)[np.argmin(points[rows == r, 0])]
                     for r in range(2, rows.max()) if np.any(rows == r)], dtype=int)


def main():
    out = sys.argv[1]
    frames = sorted(glob.glob(out + "/frames/*.vtm"))
    times = [float(l.split('timestep="')[1].split('"')[0])
             for l in open(glob.glob(out + "/*.pvd")[0]) if 'timestep="' in l]
    first = blocks(frames[0])
    heap_name = next(name for name in first if not name.startswith("wall_"))
    plate0 = first["wall_plate"]
    far0 = plate0[np.argmax(np.linalg.norm(plate0, axis=1))]
    heap0 = first[heap_name]
    spacing = np.min(np.diff(np.unique(np.round(heap0[:, 1], 9))))
    bottom_n = heap0[:, 1].min()
    flank = outermost(heap0, spacing, bottom_n)
    rows = rows_of(heap0, spacing, bottom_n)
    bottom = np.flatnonzero(rows == 0)
    base = bottom[heap0[bottom, 0] >= np.median(heap0[bottom, 0])]

    print("time_s  plate_deg  flank_to_plate_deg  flank_to_horizontal_deg  "
          "flank_speed_mm_s  base_speed_mm_s")
    previous = None
    first_motion = slide = None
    steepest = (-math.inf, None)
    flowing = []
    for t, vtm in zip(times, frames):
        b = blocks(vtm)
        plate = b["wall_plate"]
        far = plate[np.argmax(np.linalg.norm(plate, axis=1))]
        theta = math.atan2(far[1], far[0]) - math.atan2(far0[1], far0[0])
        c, s = math.cos(theta), math.sin(theta)
        local = b[heap_name] @ np.array([[c, -s], [s, c]])  # rows: (s, n) in the plate frame
        edge = local[outermost(local, spacing, bottom_n)]
        # Once the heap has run out into a layer a few rows thick there is no flank left.
        to_plate = (math.degrees(math.atan(np.polyfit(edge[:, 0], edge[:, 1], 1)[0]))
                    if len(edge) >= 3 else math.nan)
        flank_speed = base_speed = 0.0
        if previous is not None:
            dt = t - previous[0]
            flank_speed = -float(np.mean(local[flank, 0] - previous[1][flank, 0])) / dt
            base_speed = -float(np.median(local[base, 0] - previous[1][base, 0])) / dt
        previous = (t, local)
        degrees = math.degrees(theta)
        print(f"{t:6.3f} {degrees:8.3f} {to_plate:8.2f} {to_plate + degrees:8.2f} "
              f"{1e3 * flank_speed:9.3f} {1e3 * base_speed:9.3f}")
        if degrees < START:
            continue
        if first_motion is None and flank_speed > THRESHOLD:
            first_motion = (degrees, to_plate + degrees)
        if slide is None and base_speed > THRESHOLD:
            slide = degrees
        if slide is None and to_plate + degrees > steepest[0]:
            steepest = (to_plate + degrees, degrees)
        if slide is None and steepest[1] is not None and degrees > steepest[1] + 1.0:
            flowing.append(to_plate + degrees)
    print(f"flank particles {len(flank)}, base particles {len(base)}, spacing "
          f"{1e3 * spacing:.1f} mm")
    if first_motion:
        print(f"first_motion_angle_deg {first_motion[0]:.2f} (flank at {first_motion[1]:.2f} deg to the "
              f"horizontal)")
    else:
        print("first_motion_angle_deg None")
    print(f"flank_failure_angle_deg {steepest[1]:.2f} (flank at {steepest[0]:.2f} deg to the "
          f"horizontal)")
    print(f"flowing_flank_deg {np.nanmean(flowing):.2f} (mean of {len(flowing)} frames)")
    print(f"slide_angle_deg {slide:.2f}" if slide is not None else "slide_angle_deg None")


if __name__ == "__main__":
    main()
