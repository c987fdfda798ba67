#!/usr/bin/python3
"""Angle of repose of the heap left by the lifted tube, from a run's frames.

Usage: /usr/bin/python3 cases/repose/analyse.py OUT [--phi DEG] [--spacing MM]

The friction angle, spacing and body name come from the case file that summary.json names;
--phi and --spacing give those of a run that overrode them with --set, which summary.json
does not record.
Last frame, particle centres of the sand:
- free surface: the highest particle centre in each ring of width one spacing about the z
  axis (the tube's axis), heights measured from the bottom layer's centres;
- slope angle: least-squares slope of that profile over the rings whose height lies between
  20 % and 80 % of the heap height H (the rounded top and the toe left out);
- outer angle: atan(H / R), R the radius within which 99 % of the particles lie (a few
  grains rolled out along the floor do not count);
- time to rest: the first frame after the kinetic energy's peak with less than 1e-4 of it,
  the peak taken once the tube moves (the column's settling in the tube before that is not
  the heap's flow);
- particles: the count in the first and last frames (every particle has the same mass, so
  this is the mass check) and how many ended below the floor's surface or outside the floor.
"""
import glob
import json
import math
import sys
import tomllib
from pathlib import Path

import numpy as np
from vtk import vtkXMLMultiBlockDataReader
from vtk.util.numpy_support import vtk_to_numpy


def read_body(vtm, name):
    """Positions and velocities of block `name` of frame `vtm`."""
    reader = vtkXMLMultiBlockDataReader()
    reader.SetFileName(vtm)
    reader.Update()
    out = reader.GetOutput()
    for k in range(out.GetNumberOfBlocks()):
        if out.GetMetaData(k).Get(out.NAME()) == name:
            block = out.GetBlock(k)
            points = vtk_to_numpy(block.GetPoints().GetData())
            velocity = vtk_to_numpy(block.GetPointData().GetArray("velocity"))
            return points, velocity
    raise KeyError(f"{vtm} has no block {name}")


def quantity(text):
    """A case-file quantity such as '10 mm' or '30 deg' in m or degrees."""
    value, unit = text.split()
    return float(value) * {"mm": 1e-3, "m": 1.0, "cm": 1e-2, "deg": 1.0, "s": 1.0}[unit]


def surface_profile(points, spacing):
    """(ring radius, top height above the bottom layer) of every ring holding particles."""
    r = np.hypot(points[:, 0], points[:, 1])
    z = points[:, 2] - points[:, 2].min()
    ring = np.floor(r / spacing).astype(int)
    rings = np.unique(ring)
    tops = np.array([z[ring == k].max() for k in rings])
    return (rings + 0.5) * spacing, tops


def repose(points, spacing):
    radius, top = surface_profile(points, spacing)
    height = top.max()
    flank = (top >= 0.2 * height) & (top <= 0.8 * height) & (radius > radius[np.argmax(top)])
    slope, _ = np.polyfit(radius[flank], top[flank], 1)
    outer = np.percentile(np.hypot(points[:, 0], points[:, 1]), 99.0)
    return {
        "height": height,
        "outer_radius": outer,
        "slope_deg": math.degrees(math.atan(-slope)),
        "outer_deg": math.degrees(math.atan(height / outer)),
        "flank_rings": int(flank.sum()),
        "profile": list(zip(radius, top)),
    }


def main():
    out = Path(sys.argv[1])
    summary = json.loads((out / "summary.json").read_text())
    case = tomllib.loads(Path(summary["case_file"]).read_text())
    body = case["sph"]["body"][0]
    spacing = quantity(body["spacing"])
    material = next(m for m in case["material"] if m["name"] == body["material"])
    phi = quantity(material["friction_angle"])
    if "--phi" in sys.argv:
        phi = float(sys.argv[sys.argv.index("--phi") + 1])
    if "--spacing" in sys.argv:  # a run whose spacing was set with --set, in mm
        spacing = 1e-3 * float(sys.argv[sys.argv.index("--spacing") + 1])
    floor = next(w for w in case["sph"]["wall"] if w["type"] == "plane")
    floor_min = np.array([quantity(f"{v} mm") for v in floor["origin"].split()[:3]])
    floor_size = [quantity(f"{floor[k].split()[i]} mm") for k, i in (("edge_u", 0), ("edge_v", 1))]

    frames = sorted(glob.glob(str(out / "frames" / "*.vtm")))
    times = [float(l.split('timestep="')[1].split('"')[0])
             for l in open(glob.glob(str(out / "*.pvd"))[0]) if 'timestep="' in l]
    kinetic = []
    for vtm in frames:
        _, v = read_body(vtm, body["name"])
        kinetic.append(0.5 * float((v * v).sum()))  # per unit particle mass
    tube = next(w for w in case["sph"]["wall"] if "velocity_history" in w)
    moves = next(quantity(t) for t, v in tube["velocity_history"]
                 if any(float(x) != 0.0 for x in v.split()[:3]))
    lift = next(k for k, t in enumerate(times) if t >= moves)
    peak = lift + int(np.argmax(kinetic[lift:]))
    rest = next((times[k] for k in range(peak, len(frames)) if kinetic[k] < 1e-4 * kinetic[peak]),
                None)
    first, _ = read_body(frames[0], body["name"])
    last, _ = read_body(frames[-1], body["name"])
    below = int((last[:, 2] < floor_min[2]).sum())
    outside = int(((last[:, 0] < floor_min[0]) | (last[:, 0] > floor_min[0] + floor_size[0]) |
                   (last[:, 1] < floor_min[1]) | (last[:, 1] > floor_min[1] + floor_size[1])).sum())
    heap = repose(last, spacing)

    print("time_s  kinetic/peak")
    for t, e in zip(times, kinetic):
        print(f"{t:6.3f} {e / kinetic[peak]:.3e}")
    print("ring_radius_mm  top_height_mm")
    for r, z in heap["profile"]:
        print(f"{1e3 * r:7.1f} {1e3 * z:7.1f}")
    print(f"particles {len(first)} -> {len(last)}, below the floor {below}, "
          f"off the floor {outside}")
    print(f"heap_height_mm {1e3 * heap['height']:.1f}  outer_radius_mm "
          f"{1e3 * heap['outer_radius']:.1f}  flank rings fitted {heap['flank_rings']}")
    rest = f"{rest:.3f}" if rest is not None else "not reached"
    print(f"kinetic_peak_time_s {times[peak]:.3f}  time_to_rest_s {rest}  "
          f"final kinetic/peak {kinetic[-1] / kinetic[peak]:.2e}")
    print(f"friction_angle_deg {phi:.1f}  repose_slope_deg {heap['slope_deg']:.1f}  "
          f"repose_outer_deg {heap['outer_deg']:.1f}")


if __name__ == "__main__":
    main()
