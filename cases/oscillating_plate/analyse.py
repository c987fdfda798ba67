#!/usr/bin/python3
"""First-mode period and static tip deflection of the oscillating plate, from a run's frames.

Usage: /usr/bin/python3 cases/oscillating_plate/analyse.py OUT CASE.toml

The tip deflection is the mean y-displacement of the particles of the plate's last column
(initial x within one spacing of the free end). Released from rest under sudden gravity the
tip swings about its static deflection; the level it swings about is taken as the midpoint of
its extremes, refined to the time average over the whole periods between the first and the
last downward crossing of that level. The period is that span over the number of periods.
References, thin-plate theory in plane strain (bending stiffness D = E H^3 / (12 (1 - nu^2))):
T = 2 pi / omega, omega^2 = D k^4 / (rho H), k L = 1.8751, and the static tip deflection
q L^4 / (8 D) with q = rho g H. Plate length, thickness and material come from CASE.toml.
"""
import glob
import math
import sys
import tomllib

import numpy as np
from vtk import vtkXMLMultiBlockDataReader
from vtk.util.numpy_support import vtk_to_numpy

MODE_ROOT = 1.8751040687  # first root of 1 + cos(kL) cosh(kL) = 0
UNITS = {"m": 1.0, "mm": 1e-3, "kg/m^3": 1.0, "MPa": 1e6, "GPa": 1e9, "Pa": 1.0, "m/s^2": 1.0}


def quantity(text):
    *numbers, unit = text.split()
    return [float(v) * UNITS[unit] for v in numbers]


def plate_block(vtm):
    reader = vtkXMLMultiBlockDataReader()
    reader.SetFileName(vtm)
    reader.Update()
    out = reader.GetOutput()
    for k in range(out.GetNumberOfBlocks()):
        if out.GetMetaData(k).Get(out.NAME()) == "plate":
            block = out.GetBlock(k)
            points = vtk_to_numpy(block.GetPoints().GetData())
            displacement = vtk_to_numpy(block.GetPointData().GetArray("displacement"))
            return points, displacement
    raise SystemExit(f"{vtm}: no block 'plate'")


def crossings_down(times, series, level):
    found = []
    for k in range(1, len(series)):
        if series[k - 1] > level >= series[k]:
            s = (series[k - 1] - level) / (series[k - 1] - series[k])
            found.append(times[k - 1] + s * (times[k] - times[k - 1]))
    return found


def main():
    out, case_file = sys.argv[1], sys.argv[2]
    with open(case_file, "rb") as f:
        case = tomllib.load(f)
    material = case["material"][0]
    rho = quantity(material["density"])[0]
    young = quantity(material["youngs_modulus"])[0]
    nu = material["poisson_ratio"]
    body = case["sph"]["body"][0]
    spacing = quantity(body["spacing"])[0]
    upper = quantity(body["shape"]["max"])
    root = max(quantity(c["max"])[0] for c in body["clamp"])
    length, thickness = upper[0] - root, upper[1] - quantity(body["shape"]["min"])[1]
    g = -quantity(case["case"]["gravity"])[1]

    frames = sorted(glob.glob(out + "/frames/*.vtm"))
    times = [float(l.split('timestep="')[1].split('"')[0])
             for l in open(glob.glob(out + "/*.pvd")[0]) if 'timestep="' in l]
    tip = []
    for vtm in frames:
        points, u = plate_block(vtm)
        start = points - u
        tip.append(u[start[:, 0] > upper[0] - spacing, 1].mean())
    times, tip = np.array(times[:len(tip)]), np.array(tip)

    stiffness = young * thickness**3 / (12.0 * (1.0 - nu * nu))
    omega = math.sqrt(stiffness * (MODE_ROOT / length) ** 4 / (rho * thickness))
    period_ref = 2.0 * math.pi / omega
    static_ref = -rho * g * thickness * length**4 / (8.0 * stiffness)

    level = 0.5 * (tip.max() + tip.min())
    for _ in range(3):
        down = crossings_down(times, tip, level)
        if len(down) < 2:
            raise SystemExit(f"fewer than two downward crossings of {level} m: run longer")
        span = (times >= down[0]) & (times <= down[-1])
        level = np.trapz(tip[span], times[span]) / (times[span][-1] - times[span][0])
    down = crossings_down(times, tip, level)
    period = (down[-1] - down[0]) / (len(down) - 1)
    print(f"frames {len(frames)}, tip = mean of {int((start[:, 0] > upper[0] - spacing).sum())}"
          f" particles, L = {length} m, H = {thickness} m, g = {g} m/s^2")
    print(f"period_s {period:.5f} thin_plate {period_ref:.5f} error_percent "
          f"{100.0 * (period / period_ref - 1.0):+.2f} (over {len(down) - 1} periods)")
    print(f"mean_tip_deflection_m {level:.6e} static_qL4_8D {static_ref:.6e} error_percent "
          f"{100.0 * (level / static_ref - 1.0):+.2f}")
    print(f"tip_range_m {tip.min():.6e} {tip.max():.6e}")


if __name__ == "__main__":
    main()
