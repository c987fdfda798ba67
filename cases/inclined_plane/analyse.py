#!/usr/bin/python3
"""Velocity profile of the steady inclined-plane flow (cases/inclined_plane) against Bagnold's.

Usage:
    /usr/bin/python3 cases/inclined_plane/analyse.py OUT_DIR [OUT_DIR ...] [--from 1.5]
        [--label TEXT ...] [--svg FILE]

For each run: the frames from --from seconds on (the steady flow) are averaged in bins of one
particle row: the mean velocity along the slope u, the ratio |sigma_xy| / p of the rows' mean
stresses and the mean inertial number I. Printed per row beside the mu(I) solution of the case
file's header (GDR MiDi 2004; Jop, Forterre & Pouliquen 2006):
    I = I0 (tan theta - mu_s) / (mu_2 - tan theta),
    u(y) = (2/3) (I / d) sqrt(rho g cos theta / rho_s) (H^(3/2) - (H - y)^(3/2)),
with y from the layer's base: the lowest row's centre less half a spacing (the layer's initial
box). The parameters are those of cases/inclined_plane/bagnold_mu_i*.toml. --svg draws u(y)/H of
every run beside the formula (matplotlib).
"""

import argparse
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                "scripts"))
import vtk_frames  # noqa: E402
from vtk.util.numpy_support import vtk_to_numpy  # noqa: E402

THETA = math.radians(25.0)
G = 9.81
RHO, RHO_S, D = 1470.0, 2450.0, 0.5e-3
MU_S, MU_2, I0 = math.tan(math.radians(20.9)), math.tan(math.radians(32.76)), 0.279
H = 0.02
I_STEADY = I0 * (math.tan(THETA) - MU_S) / (MU_2 - math.tan(THETA))


def bagnold(y):
    """The mu(I) velocity at height y above the base (m/s)."""
    depth = np.clip(H - np.asarray(y), 0.0, None)
    return (2.0 / 3.0) * (I_STEADY / D) * math.sqrt(RHO * G * math.cos(THETA) / RHO_S) * (
        H ** 1.5 - depth ** 1.5)


def layer_block(vtm):
    for name, data in vtk_frames.blocks(vtm):
        if name == "layer":
            return data
    raise SystemExit(f"{vtm}: no block 'layer'")


def profile(out, start):
    """Rows of (height above base, u, |sigma_xy|/p, I) averaged over the frames from `start`."""
    frames = [(t, f) for t, f in vtk_frames.frames_of(out) if t >= start - 1e-9]
    if not frames:
        raise SystemExit(f"{out}: no frame at or after {start} s")
    first = layer_block(frames[0][1])
    y_start = vtk_to_numpy(first.GetPoints().GetData())[:, 1] - vtk_to_numpy(
        first.GetPointData().GetArray("displacement"))[:, 1]
    rows = np.unique(np.round(y_start, 7))
    spacing = float(np.min(np.diff(rows)))
    base = rows[0] - 0.5 * spacing
    row_of = np.searchsorted(rows, np.round(y_start, 7))
    u = np.zeros(len(rows))
    shear = np.zeros(len(rows))
    pressure = np.zeros(len(rows))
    inertial = [[] for _ in rows]  # per row, the frames' means where I is defined (p > 0)
    for _, vtm in frames:
        data = layer_block(vtm).GetPointData()
        velocity = vtk_to_numpy(data.GetArray("velocity"))
        stress = vtk_to_numpy(data.GetArray("stress"))
        number = vtk_to_numpy(data.GetArray("inertial_number"))
        for k in range(len(rows)):
            m = row_of == k
            u[k] += velocity[m, 0].mean()
            shear[k] += abs(stress[m, 3].mean())
            pressure[k] += -stress[m, :3].sum(axis=1).mean() / 3.0
            defined = number[m][np.isfinite(number[m])]
            if defined.size:
                inertial[k].append(defined.mean())
    n = len(frames)
    mean_i = np.array([np.mean(values) if values else math.nan for values in inertial])
    return rows - base, u / n, shear / np.maximum(pressure, 1e-30), mean_i, spacing


def write_svg(path, runs):
    import matplotlib
    matplotlib.use("Agg")
    matplotlib.rcParams["svg.hashsalt"] = "grainload"
    import matplotlib.pyplot as plt
    figure, axes = plt.subplots(figsize=(6.5, 4.6), layout="constrained")
    y = np.linspace(0.0, H, 200)
    axes.plot(bagnold(y), y / H, "k-", label=f"μ(I), Bagnold profile (I = {I_STEADY:.3f})")
    for (label, (height, u, _, _, _)), marker in zip(runs, "osd^v"):
        axes.plot(u, height / H, marker + "-", label=label)
    axes.set_xlabel("velocity along the slope u, m/s")
    axes.set_ylabel("height above the base y / H")
    axes.set_xlim(0, None)
    axes.set_ylim(0, 1.05)
    axes.grid(True, alpha=0.3)
    axes.legend(loc="lower right", fontsize="small")
    figure.savefig(path, metadata={"Date": None})
    plt.close(figure)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("out", nargs="+")
    ap.add_argument("--from", dest="start", type=float, default=1.5)
    ap.add_argument("--label", action="append", default=[])
    ap.add_argument("--svg")
    args = ap.parse_args()
    runs = []
    for k, out in enumerate(args.out):
        label = args.label[k] if k < len(args.label) else out
        height, u, ratio, inertial, spacing = profile(out, args.start)
        runs.append((label, (height, u, ratio, inertial, spacing)))
        reference = bagnold(height)
        print(f"{label}: spacing {spacing * 1e3:g} mm, mean of the frames from {args.start} s")
        print("   y/H    u m/s   mu(I) u   ratio   |s_xy|/p      I")
        for k in range(len(height)):
            print(f"  {height[k] / H:5.3f}  {u[k]:7.4f}  {reference[k]:8.4f}  {u[k] / reference[k]:6.3f}"
                  f"  {ratio[k]:8.3f}  {inertial[k]:7.4f}")
        top = int(np.argmax(height))
        print(f"  surface row: u = {u[top]:.4f} m/s against {reference[top]:.4f} "
              f"({u[top] / reference[top]:.3f}); tan theta = {math.tan(THETA):.3f}, "
              f"mu_s = {MU_S:.3f}")
    if args.svg:
        write_svg(args.svg, runs)
        print(f"written: {args.svg}")


if __name__ == "__main__":
    main()
