"""The DEM silo against Janssen (1895): reads OUT/summary.json (the floor's and each wall
band's vertical load and normal force) and the last frame (the grains), prints the fill's bulk
density, its equivalent height, the wall's share of the weight and the product mu K that gives
it, then per band the wall friction the run shows beside Janssen's with that mu K, the band's
pressure p_h (normal force over area), the mean vertical stress p_v at its middle (the weight
above less the wall friction above, over the section: equilibrium, no model), K = p_h / p_v,
and the friction mobilised (vertical load over normal force, at most mu_w);
writes OUT/silo_janssen_dem.png.

Janssen: at depth s below the surface, p_v(s) = rho_b g D / (4 mu K) (1 - exp(-4 mu K s / D));
the wall carries what the slice's weight does not pass down, so a band from depth s_a to s_b
carries rho_b g A (s_b - s_a) - A (p_v(s_b) - p_v(s_a)). Only the product mu K enters. The bulk density rho_b is the grains'
volume fraction between 2 and 8 grain radii above the floor times their density, counted by
slicing every sphere exactly; the height H = W / (rho_b g A) is the column of that density
which weighs what the grains weigh (the surface's heap folded in).
Usage: /usr/bin/python3 cases/silo_janssen/analyse_dem.py OUT [RADIUS_M BAND_M]"""
import glob
import json
import math
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import vtk  # noqa: E402
from vtk.util.numpy_support import vtk_to_numpy  # noqa: E402

G, MU_WALL, DENSITY = 9.81, 0.4, 2650.0  # the case's gravity, wall friction, grain density


def grains(out):
    reader = vtk.vtkXMLMultiBlockDataReader()
    reader.SetFileName(sorted(glob.glob(os.path.join(out, "frames", "*.vtm")))[-1])
    reader.Update()
    block = reader.GetOutput().GetBlock(0)
    centres = vtk_to_numpy(block.GetPoints().GetData())
    radii = vtk_to_numpy(block.GetPointData().GetArray("radius"))
    return centres, radii


def slab_volume(z, r, low, high):
    """Volume of the spheres (centre heights z, radii r) between the planes low and high."""
    a = np.clip(low - z, -r, r)
    b = np.clip(high - z, -r, r)
    return np.sum(math.pi * ((r * r * b - b**3 / 3.0) - (r * r * a - a**3 / 3.0)))


def janssen_band(s_a, s_b, rho_b, diameter, k):
    area = math.pi * diameter**2 / 4.0
    scale = rho_b * G * diameter / (4.0 * MU_WALL * k)
    p_v = lambda s: scale * (1.0 - math.exp(-4.0 * MU_WALL * k * s / diameter))  # noqa: E731
    return rho_b * G * area * (s_b - s_a) - area * (p_v(s_b) - p_v(s_a))


def fit_k(share, height, diameter):
    """The K whose wall share 1 - (1 - exp(-x)) / x, x = 4 mu K H / D, is `share` (bisection)."""
    low, high = 1e-6, 10.0
    for _ in range(200):
        k = 0.5 * (low + high)
        x = 4.0 * MU_WALL * k * height / diameter
        if 1.0 - (1.0 - math.exp(-x)) / x < share:
            low = k
        else:
            high = k
    return 0.5 * (low + high)


def main():
    out = sys.argv[1]
    radius = float(sys.argv[2]) if len(sys.argv) > 2 else 0.075
    band = float(sys.argv[3]) if len(sys.argv) > 3 else 0.05
    diameter, area = 2.0 * radius, math.pi * radius**2
    with open(os.path.join(out, "summary.json")) as f:
        results = json.load(f)["results"]
    bands = sorted(n[len("wall_"):-len("_force_z")] for n in results
                   if n.startswith("wall_band") and n.endswith("_force_z"))
    floor = -results["wall_floor_force_z"]["value"]
    loads = [-results["wall_%s_force_z" % b]["value"] for b in bands]
    normals = [results["wall_%s_normal_force" % b]["value"] for b in bands]
    centres, r = grains(out)
    z = centres[:, 2]
    weight = DENSITY * G * np.sum(4.0 / 3.0 * math.pi * r**3)
    low, high = 2.0 * r.max(), 8.0 * r.max()
    rho_b = DENSITY * slab_volume(z, r, low, high) / (area * (high - low))
    height = weight / (rho_b * G * area)
    share = sum(loads) / weight
    k = fit_k(share, height, diameter)
    print("grains %d, weight %.4f N, floor %.4f N, walls %.4f N (sum/weight - 1 = %.2e)"
          % (len(r), weight, floor, sum(loads), (floor + sum(loads)) / weight - 1.0))
    print("bulk density %.1f kg/m^3 (solid fraction %.3f), equivalent height %.4f m, top grain %.4f m"
          % (rho_b, rho_b / DENSITY, height, (z + r).max()))
    print("wall share %.4f -> mu K = %.4f (K = %.4f at mu_w = %.1f)" % (share, MU_WALL * k, k, MU_WALL))
    print("band  from_m  to_m   run_N    janssen_N  run/janssen  p_h_Pa  p_v_Pa  K  mobilised")
    rows = []
    column = rho_b * G * area  # weight per metre of the equivalent column
    for index, (b, load, normal) in enumerate(zip(bands, loads, normals)):
        bottom = band * int(b[len("band"):])
        s_a = min(max(height - bottom - band, 0.0), height)
        s_b = min(max(height - bottom, 0.0), height)
        ref = janssen_band(s_a, s_b, rho_b, diameter, k)
        rows.append((bottom, load, ref))
        middle = bottom + band / 2
        above = sum(loads[index + 1:]) + load / 2
        p_v = (column * max(height - middle, 0.0) - above) / area
        p_h = normal / (2.0 * math.pi * radius * band)
        if ref > 1e-9 and p_v > 0:
            print("%-5s %.3f  %.3f  %8.4f  %8.4f   %.3f  %7.1f  %7.1f  %.3f  %.3f"
                  % (b, bottom, bottom + band, load, ref, load / ref, p_h, p_v, p_h / p_v,
                     load / normal))
    fig, ax = plt.subplots(figsize=(5, 4))
    ax.barh([b + band / 2 for b, _, _ in rows], [l for _, l, _ in rows], height=0.8 * band,
            label="DEM, wall band load", color="tab:blue", alpha=0.6)
    ax.plot([j for _, _, j in rows], [b + band / 2 for b, _, _ in rows], "ko-",
            label="Janssen, K = %.2f" % k)
    ax.set_xlabel("vertical load on the band [N]")
    ax.set_ylabel("band height above the floor [m]")
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(out, "silo_janssen_dem.png"), dpi=120)


if __name__ == "__main__":
    main()
