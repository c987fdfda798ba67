"""The silo at rest against Janssen: reads OUT/wall_forces.csv (the left wall's 0.2 m bands)
and the last frame's sand particles, prints per band the wall pressure p_h = F_x / band
height, the wall friction traction against mu p_h, the mean vertical stress p_v of the sand in
the band, the K the run shows (p_h / p_v), and Janssen's band means for K = 1 - sin(phi) and
1.1 (1 - sin(phi)); writes OUT/silo_pressure.png.
Usage: /usr/bin/python3 cases/silo/analyse.py OUT [spacing_mm]"""
import csv
import glob
import math
import os
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader

MU = 0.4                      # wall friction coefficient of the case
PHI = math.radians(30.0)      # the sand's friction angle
G = 9.81
BANDS = [(f"left{k}", 0.2 * k, 0.2 * (k + 1)) for k in range(6)]


def janssen_band_mean(gamma, d, k, z_top, z_bottom):
    """Mean of p_h = gamma D/(2 mu) (1 - exp(-z/z0)) over depths [z_top, z_bottom] (z >= 0),
    z0 = D / (2 K mu): the plane-strain slot, A/U = D/2 (Janssen 1895; EN 1991-4 Eq. 5.5). gamma D
    is the weight per metre of height and per metre of depth, M g / H, whatever the packing."""
    z0 = d / (2.0 * k * MU)
    a, b = max(z_top, 0.0), max(z_bottom, 0.0)
    if b <= a:
        return 0.0
    integral = (b - a) - z0 * (math.exp(-a / z0) - math.exp(-b / z0))
    return gamma * d / (2.0 * MU) * integral / (z_bottom - z_top)


def read_particles(path):
    """Positions (n x 3, m) and stress (n x 6, Pa: XX YY ZZ XY YZ XZ) of a body's .vtp."""
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    data = reader.GetOutput()
    if data.GetNumberOfPoints() == 0:
        sys.exit(f"analyse.py: no particles in {path}")
    stress = data.GetPointData().GetArray("stress")
    if stress is None:
        sys.exit(f"analyse.py: {path} has no point array 'stress'")
    return vtk_to_numpy(data.GetPoints().GetData()), vtk_to_numpy(stress)


def main(out, spacing):
    rows = list(csv.DictReader(open(os.path.join(out, "wall_forces.csv"))))
    t_end = max(float(r["time_s"]) for r in rows)
    force = {r["wall"]: (float(r["force_x_N"]), float(r["force_y_N"]))
             for r in rows if float(r["time_s"]) == t_end}
    frame = sorted(glob.glob(os.path.join(out, "frames", "*_[0-9]*[0-9]")))[-1]
    x, stress = read_particles(os.path.join(frame, "sand.vtp"))
    mass = float(len(x)) * 1500.0 * spacing ** 2
    d = x[:, 0].max() - x[:, 0].min() + spacing       # the sand's width
    top = np.sort(x[:, 1])[-max(3, len(x) // 200):].mean() + spacing / 2  # the surface
    height = top - (x[:, 1].min() - spacing / 2)
    gamma = mass * G / height / d      # so that gamma D = M g / H
    print(f"t = {t_end} s, {len(x)} particles, width D = {d:.4f} m, surface at {top:.4f} m, "
          f"bulk unit weight {gamma:.1f} N/m^3")
    k_low, k_high = 1.0 - math.sin(PHI), 1.1 * (1.0 - math.sin(PHI))
    inner = [k for k in range(1, 5)]   # bands clear of the floor and the surface
    print("band_m  depth_m  p_h_Pa  friction/(mu p_h)  p_v_Pa  K_run  "
          "Janssen(K=%.3f)  Janssen(K=%.3f)  p_h/Janssen_mid" % (k_low, k_high))
    table = []
    for name, y0, y1 in BANDS:
        fx, fy = force[name]
        p_h = -fx / (y1 - y0)            # the left wall is pushed to -x
        in_band = (x[:, 1] >= y0) & (x[:, 1] < y1)
        p_v = -stress[in_band, 1].mean() if in_band.any() else float("nan")
        z_top, z_bottom = top - y1, top - y0
        lo = janssen_band_mean(gamma, d, k_low, z_top, z_bottom)
        hi = janssen_band_mean(gamma, d, k_high, z_top, z_bottom)
        ratio = p_h / (0.5 * (lo + hi)) if lo > 0 else float("nan")
        table.append((0.5 * (y0 + y1), 0.5 * (z_top + z_bottom), p_h, lo, hi, p_h / p_v))
        print(f"{y0:.1f}-{y1:.1f}  {0.5 * (z_top + z_bottom):6.3f}  {p_h:7.1f}  "
              f"{-fy / (MU * p_h * (y1 - y0)) if p_h > 0 else float('nan'):6.3f}  {p_v:7.1f}  "
              f"{p_h / p_v:5.3f}  {lo:7.1f}  {hi:7.1f}  {ratio:5.3f}")
    k_run = float(np.mean([table[k][5] for k in inner]))
    print(f"K the run shows (p_h / p_v, bands 0.2-1.0 m): {k_run:.3f}")
    for k in inner:
        name, y0, y1 = BANDS[k]
        j = janssen_band_mean(gamma, d, k_run, top - y1, top - y0)
        print(f"  band {y0:.1f}-{y1:.1f} m: p_h / Janssen(K_run) = {table[k][2] / j:.3f}")
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return
    z = np.linspace(0.0, top, 100)
    fig, ax = plt.subplots(figsize=(5, 5))
    for k, style in ((k_low, "--"), (k_high, ":")):
        z0 = d / (2 * k * MU)
        ax.plot(gamma * d / (2 * MU) * (1 - np.exp(-z / z0)), z, style, label=f"Janssen K = {k:.3f}")
    ax.plot([r[2] for r in table], [r[1] for r in table], "o-", label="run, per 0.2 m band")
    ax.invert_yaxis()
    ax.set_xlabel("horizontal wall pressure p_h (Pa)")
    ax.set_ylabel("depth below the surface z (m)")
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(out, "silo_pressure.png"), dpi=120)


if __name__ == "__main__":
    main(sys.argv[1], float(sys.argv[2]) / 1000.0 if len(sys.argv) > 2 else 0.025)
