"""The filled cylinder against Janssen (1895): reads the last frame of OUT (the sand particles
and the two coupled halves' `contact_pressure`, `friction_traction`), prints per 50 mm of
height the sand's mean vertical stress p_v, its mean horizontal stress, the K the run shows,
the wall pressure p_h and friction traction and their ratio (the mobilised friction), then
Janssen's p_v(z) and the wall's share of the weight with the run's own K and mobilised
friction; writes OUT/silo_janssen_fill.png.

The sand's outer particles stand off the wall by the contact potential's reach, so the column
has its own radius r_s (the outermost centres plus half a spacing) and Janssen's A/U is
r_s / 2; the wall pressure is the sand's lateral stress spread from its perimeter onto the
wall's, p_h,wall = sigma_h r_s / R.
Usage: /usr/bin/python3 cases/silo_janssen/analyse.py OUT"""
import glob
import math
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import vtk  # noqa: E402
from vtk.util.numpy_support import vtk_to_numpy  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
from shell_membrane import hoop_and_meridional  # noqa: E402

RHO, G, R, SPACING, BIN = 1600.0, 9.81, 0.15, 0.025, 0.05  # the case's sand, wall radius


def last_frame(out):
    reader = vtk.vtkXMLMultiBlockDataReader()
    reader.SetFileName(sorted(glob.glob(os.path.join(out, "frames", "*.vtm")))[-1])
    reader.Update()
    blocks = reader.GetOutput()
    sand, shells = None, []
    for i in range(blocks.GetNumberOfBlocks()):
        name = blocks.GetMetaData(i).Get(vtk.vtkCompositeDataSet.NAME())
        block = blocks.GetBlock(i)
        if name == "sand":
            sand = block
        elif block is not None and block.GetPointData().GetArray("contact_pressure"):
            shells.append(block)
    return sand, shells


def array(block, name):
    return vtk_to_numpy(block.GetPointData().GetArray(name))


def hoop_force_table(shells):
    """Membrane theory of a cylinder under wall pressure: the hoop force N_theta = p_h R, and the
    axial force at the base carries the wall's friction load: N_y = -F_wall / (2 pi R). Which of
    the elements' membrane axes runs round the hoop is read from their first edges
    (scripts/shell_membrane.py)."""
    print(" y m   N_theta N/m  p_h R N/m  N_y N/m")
    parts = [hoop_and_meridional(shell, 1) for shell in shells]
    centres, hoop, axial, pressure = (np.concatenate([part[k] for part in parts]) for k in range(4))
    y = centres[:, 1]
    for y0 in np.arange(0.0, y.max(), BIN):
        inside = (y >= y0) & (y < y0 + BIN)
        print(f"{y0 + BIN / 2:5.3f} {hoop[inside].mean():10.2f} {pressure[inside].mean() * R:10.2f} "
              f"{axial[inside].mean():8.2f}")


def main(out):
    sand, shells = last_frame(out)
    x = vtk_to_numpy(sand.GetPoints().GetData())
    stress = array(sand, "stress")
    bottom, top = x[:, 1].min() - SPACING / 2, x[:, 1].max() + SPACING / 2
    r_s = np.hypot(x[:, 0], x[:, 2]).max() + SPACING / 2
    wall_y = np.concatenate([vtk_to_numpy(s.GetPoints().GetData())[:, 1] for s in shells])
    pressure = np.concatenate([array(s, "contact_pressure") for s in shells])
    traction = np.concatenate([array(s, "friction_traction")[:, 1] for s in shells])
    rows, ks, mobilised = [], [], []
    print(" y0 m   p_v Pa  sigma_h Pa    K   p_h wall Pa  tau Pa  tau/p_h")
    for y0 in np.arange(bottom, top - 1e-9, BIN):
        inside = (x[:, 1] >= y0) & (x[:, 1] < y0 + BIN)
        on_wall = (wall_y >= y0) & (wall_y < y0 + BIN)
        if inside.sum() == 0 or on_wall.sum() == 0:
            continue
        p_v = -stress[inside, 1].mean()
        sigma_h = -(stress[inside, 0] + stress[inside, 2]).mean() / 2
        p_h, tau = pressure[on_wall].mean(), -traction[on_wall].mean()
        rows.append((y0 + BIN / 2, p_v, sigma_h, p_h))
        ks.append(sigma_h / p_v)
        mobilised.append(tau / p_h if p_h > 0 else float("nan"))
        print(f"{y0:5.3f} {p_v:8.1f} {sigma_h:10.1f} {ks[-1]:6.3f} {p_h:10.1f} {tau:8.1f} "
              f"{mobilised[-1]:7.3f}")
    height = top - bottom
    # The unit weight of the column as the lattice packs it (each particle rho s^3 of mass):
    # its weight over its volume pi r_s^2 H, as Janssen's gamma A is the weight per height.
    gamma = len(x) * RHO * SPACING ** 3 * G / (math.pi * r_s ** 2 * height)
    k = float(np.median(ks))
    mu = float(np.nanmedian(mobilised))
    z0 = (r_s / 2) / (mu * k)
    share = 1 - z0 / height * (1 - math.exp(-height / z0))
    print(f"column: r_s = {r_s:.4f} m, H = {height:.3f} m; run's K (median) = {k:.3f}, "
          f"mobilised friction (median) = {mu:.3f}, unit weight {gamma:.0f} N/m^3; Janssen "
          f"z0 = {z0:.3f} m, wall share of the weight {share:.3f}")
    y = np.array([r[0] for r in rows])
    depth = top - y
    janssen_pv = gamma * z0 * (1 - np.exp(-depth / z0))
    hoop_force_table(shells)
    plt.figure(figsize=(5, 4))
    plt.plot([r[1] for r in rows], y, "o", label="sand p_v (run)")
    plt.plot(janssen_pv, y, "-", label=f"Janssen p_v, K = {k:.2f}, μ = {mu:.2f}")
    plt.plot([r[3] for r in rows], y, "s", label="wall p_h (run)")
    plt.plot(janssen_pv * k * r_s / R, y, "--", label="Janssen K p_v r_s / R")
    plt.plot(gamma * depth, y, ":", label="hydrostatic γ z")
    plt.xlabel("stress [Pa]")
    plt.ylabel("height y [m]")
    plt.legend(fontsize=7)
    plt.tight_layout()
    plt.savefig(os.path.join(out, "silo_janssen_fill.png"), dpi=120)


if __name__ == "__main__":
    main(sys.argv[1])
