#!/usr/bin/python3
"""Events of the tipping sand cone (thesis section 7.3) from a run's frames.

Usage: /usr/bin/python3 cases/tipping_cone/analyse.py OUT

The plate turns about the hinge line x = 0 (axis -y), lifting its edge x = 0.6 m. Positions are
taken in the plate's frame: s along the plate (from the hinge), n normal to it; the plate's
angle theta comes from its lifted edge (the shell block's largest z at the edge, over 0.6 m).
Particle sets, chosen in the first frame:
- flank: the particles of the cone's surface on the hinge side (the side that steepens as the
  plate turns: its angle to the horizontal is the flank's 30 deg plus theta), above the
  bottom two rows;
- base: the bottom row's particles on the lifted side, away from where avalanching sand runs.
Events (speeds relative to the plate, down the plate, i.e. towards the hinge):
- flank avalanche: the first frame at which the flank's mean speed exceeds 5 mm/s while the
  base is at rest;
- slide: the first frame at which the base's median speed exceeds 5 mm/s.
Per frame it prints theta, both speeds, the plate's largest deflection out of its plane and
its largest von Mises stress (top, middle or bottom of the section).
"""
import glob
import math
import sys

import numpy as np
from vtk import vtkXMLMultiBlockDataReader
from vtk.util.numpy_support import vtk_to_numpy

THRESHOLD = 5e-3  # m/s
LENGTH = 0.6      # plate length from the hinge [m]


def read(vtm):
    reader = vtkXMLMultiBlockDataReader()
    reader.SetFileName(vtm)
    reader.Update()
    out = reader.GetOutput()
    blocks = {}
    for k in range(out.GetNumberOfBlocks()):
        name = out.GetMetaData(k).Get(out.NAME())
        blocks[name] = out.GetBlock(k)
    return blocks


def points(block):
    return vtk_to_numpy(block.GetPoints().GetData())


def point_array(block, name):
    return vtk_to_numpy(block.GetPointData().GetArray(name))


def cell_array(block, name):
    return vtk_to_numpy(block.GetCellData().GetArray(name))


def plate_angle(plate):
    x = points(plate)
    return math.asin(min(1.0, max(0.0, x[:, 2].max()) / LENGTH))


def in_plate_frame(x, theta):
    s = x[:, 0] * math.cos(theta) + x[:, 2] * math.sin(theta)
    n = -x[:, 0] * math.sin(theta) + x[:, 2] * math.cos(theta)
    return s, n


def main(out):
    frames = sorted(glob.glob(out + "/frames/*.vtm"))
    times = []
    with open(glob.glob(out + "/*.pvd")[0]) as pvd:
        for line in pvd:
            if "timestep=" in line:
                times.append(float(line.split('timestep="')[1].split('"')[0]))
    first = read(frames[0])
    cone = points(first["cone"])
    rows = np.round((cone[:, 2] - cone[:, 2].min()) / 0.02).astype(int)
    centre = cone[:, 0].mean()
    radius = np.hypot(cone[:, 0] - centre, cone[:, 1] - cone[:, 1].mean())
    outer = np.zeros(len(cone), dtype=bool)
    for r in range(rows.max() + 1):
        in_row = rows == r
        if in_row.any():
            outer |= in_row & (radius >= radius[in_row].max() - 0.021)
    flank = outer & (rows >= 2) & (cone[:, 0] < centre)
    base = (rows == 0) & (cone[:, 0] > centre)
    previous = None
    avalanche = slide = None
    print("t [s]  theta [deg]  flank [mm/s]  base [mm/s]  deflection [mm]  von Mises [MPa]")
    for time, frame in zip(times, frames):
        blocks = read(frame)
        theta = plate_angle(blocks["plate"])
        x = points(blocks["cone"])
        s, _ = in_plate_frame(x, theta)
        plate = blocks["plate"]
        _, n_plate = in_plate_frame(points(plate), theta)
        stress = max(cell_array(plate, name).max()
                     for name in ("von_mises_top", "von_mises_middle", "von_mises_bottom"))
        if previous is not None:
            dt = time - previous[0]
            speed = -(s - previous[1]) / dt  # down the plate: towards the hinge
            flank_speed = speed[flank].mean()
            base_speed = np.median(speed[base])
            print(f"{time:5.3f}  {math.degrees(theta):11.2f}  {1e3 * flank_speed:12.2f}  "
                  f"{1e3 * base_speed:11.2f}  {1e3 * np.abs(n_plate).max():15.3f}  "
                  f"{stress / 1e6:15.2f}")
            if slide is None and base_speed > THRESHOLD:
                slide = (time, math.degrees(theta))
            if avalanche is None and slide is None and flank_speed > THRESHOLD:
                avalanche = (time, math.degrees(theta))
        previous = (time, s)
    for name, event, thesis in (("flank avalanche", avalanche, 0.2), ("slide", slide, 0.45)):
        if event is None:
            print(f"{name}: not seen (thesis {thesis} s)")
        else:
            print(f"{name}: t = {event[0]:.3f} s at theta = {event[1]:.2f} deg "
                  f"(thesis {thesis} s)")


if __name__ == "__main__":
    main(sys.argv[1])
