"""The circular silo with its conical hopper against Janssen (1895) and Beverloo (1961).

Reads OUT (a run of silo_hopper.toml or silo_hopper_small.toml) and prints:
- per ring of the unrolled cylinder (wall_maps/rest_window.csv and flow_window.csv, the ring
  means over the map's three sectors) the wall pressure at rest, its mean and maximum in the
  discharge and their ratios to rest (EN 1991-4 designs slender silos for 1.15 at discharge),
  and the mobilised wall friction tau / (mu p);
- Janssen's p_h(z) = gamma A / (mu U) (1 - exp(-z / z0)), z0 = A / (K mu U), with z from the
  fill's surface (the frame at the rest window's end: the 95th percentile of the sand's
  heights plus half a spacing; the source's last rows leave it uneven), with the column's own
  unit weight gamma (its weight over its volume A (surface - transition): the fill spread
  from the source's radius to the wall's and is looser than the material's density), with the
  friction the wall mobilises (the median over the filled rings of tau / p) and with the K
  that fits the run's ring pressures (least squares), beside 1 - sin(phi) and EN 1991-4's
  1.1 (1 - sin(phi));
- the steady discharge rate of the quarter (summary.json) times four against Beverloo's
  W = C rho_b sqrt(g) (D - k d)^2.5 for a circular outlet, C = 0.58, for the outlet in effect,
  with the column's bulk density rho_b = gamma / g: d = 0 (a continuum has no grain) and
  k d = 1.4 spacings (Beverloo's k for spheres with the particles as grains) bracket it.
The sand's outer particles stand off the wall by the contact potential's reach, so Janssen's
A/U is the column's radius over two: r_s = R - (stand-off) with the stand-off read from the
frame (the outermost centres plus half a spacing), and p_h on the wall is the column's lateral
stress spread onto the wall's perimeter, sigma_h r_s / R.
The spacing and the transition's height are read from the case file the run names in its
summary.json. Writes OUT/silo_hopper_pressure.png.
Usage: /usr/bin/python3 cases/silo_hopper/analyse.py OUT
"""
import csv
import json
import math
import os
import sys
import tomllib

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from vtk.util.numpy_support import vtk_to_numpy  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
from vtk_frames import blocks, frames_of  # noqa: E402

RHO, G, R, MU, PHI = 1600.0, 9.81, 0.2, 0.4, math.radians(30.0)  # the cases' sand and silo
OUTLET = 0.1  # the outlet in effect (drawn 0.1 m + 4h)
UNITS = {"m": 1.0, "mm": 1e-3}
BEVERLOO_C = 0.58


def ring_means(path, column):
    """Axial centres and the sector mean of one column of a window map, per ring."""
    rings = {}
    with open(path) as f:
        for row in csv.DictReader(f):
            rings.setdefault(float(row["axial_m"]), []).append(float(row[column]))
    axial = np.array(sorted(rings))
    return axial, np.array([np.mean(rings[a]) for a in axial])


def sand_points(out, time):
    """The sand particles' positions in the frame nearest `time`."""
    _, vtm = min(frames_of(out), key=lambda frame: abs(frame[0] - time))
    for name, block in blocks(vtm):
        if name == "sand":
            return vtk_to_numpy(block.GetPoints().GetData())
    raise SystemExit("no sand block in " + vtm)


def janssen(depth, k, r_s, mu, gamma):
    """Janssen's wall pressure on the wall of radius R from the column of radius r_s and unit
    weight gamma, with the wall friction coefficient mu that the wall mobilises."""
    hydraulic = r_s / 2.0
    z0 = hydraulic / (k * mu)
    return gamma * hydraulic / mu * (1.0 - np.exp(-depth / z0)) * r_s / R


def metres(quantity):
    """A length of the case file ("15 mm", "0 0 192.26 mm": its last component) in m."""
    *numbers, unit = quantity.split()
    return float(numbers[-1]) * UNITS[unit]


def main(out):
    whole = json.load(open(os.path.join(out, "summary.json")))
    summary = whole["results"]
    with open(whole["case_file"], "rb") as f:
        case = tomllib.load(f)
    spacing = metres(case["sph"]["body"][0]["spacing"])
    z_t = metres(case["sph"]["wall_map"][0]["origin"])  # the transition: the maps' origin
    particle_mass = RHO * spacing**3
    rest = os.path.join(out, "wall_maps", "rest_window.csv")
    with open(rest) as f:
        rest_end = float(next(csv.DictReader(f))["window_end_s"])
    axial, p_rest = ring_means(rest, "mean_pressure_Pa")
    _, tau_rest = ring_means(rest, "mean_shear_axial_Pa")
    sand = sand_points(out, rest_end)
    in_cylinder = sand[sand[:, 2] > z_t]
    top = np.percentile(in_cylinder[:, 2], 95) + spacing / 2
    r_s = np.hypot(in_cylinder[:, 0], in_cylinder[:, 1]).max() + spacing / 2
    gamma = len(in_cylinder) * particle_mass * G / (math.pi * r_s**2 / 4 * (top - z_t))
    depth = top - (z_t + axial)
    filled = (depth > 0) & (p_rest > 0)
    mobilised = float(np.median(-tau_rest[filled] / p_rest[filled]))
    best = min(np.linspace(0.2, 1.5, 1301),
               key=lambda k: np.sum((janssen(depth[filled], k, r_s, mobilised, gamma) -
                                     p_rest[filled]) ** 2))
    print(f"fill surface z = {top:.3f} m ({top - z_t:.3f} m above the transition), column "
          f"radius r_s = {r_s:.4f} m (stand-off {R - r_s:.4f} m), unit weight {gamma:.0f} N/m^3 "
          f"(the material's {RHO * G:.0f})")
    print(f"wall friction mobilised: {mobilised:.3f} (median tau / p; mu = {MU})")
    print(f"K fitted to the ring pressures: {best:.3f}; 1 - sin(phi) = {1 - math.sin(PHI):.3f}, "
          f"EN 1991-4 1.1 (1 - sin(phi)) = {1.1 * (1 - math.sin(PHI)):.3f}")
    flow = os.path.join(out, "wall_maps", "flow_window.csv")
    has_flow = os.path.exists(flow)
    if has_flow:
        _, p_flow = ring_means(flow, "mean_pressure_Pa")
        _, p_flow_max = ring_means(flow, "max_pressure_Pa")
    print(" z-z_t m  depth m  p_rest Pa  Janssen(K) Pa  tau/(mu p)" +
          ("  p_flow mean Pa  /rest  p_flow max Pa  /rest" if has_flow else ""))
    for i, a in enumerate(axial):
        line = (f"{a:8.3f} {depth[i]:8.3f} {p_rest[i]:10.1f} "
                f"{janssen(max(depth[i], 0.0), best, r_s, mobilised, gamma):14.1f} "
                f"{-tau_rest[i] / (MU * p_rest[i]) if p_rest[i] > 0 else float('nan'):11.3f}")
        if has_flow and p_rest[i] > 0:
            line += (f" {p_flow[i]:15.1f} {p_flow[i] / p_rest[i]:6.2f} {p_flow_max[i]:14.1f}"
                     f" {p_flow_max[i] / p_rest[i]:6.2f}")
        print(line)
    rate = 4.0 * summary["sink_below_steady_rate"]["value"]
    bulk = gamma / G
    for grain in (0.0, 1.4 * spacing):
        beverloo = BEVERLOO_C * bulk * math.sqrt(G) * (OUTLET - grain) ** 2.5
        print(f"steady discharge rate (whole silo): {rate:.2f} kg/s; Beverloo (C = {BEVERLOO_C}, "
              f"rho_b = {bulk:.0f} kg/m^3, D = {OUTLET} m, k d = {grain:.3f} m): "
              f"{beverloo:.2f} kg/s; ratio {rate / beverloo:.3f}")
    fig, ax = plt.subplots(figsize=(5, 6))
    ax.plot(p_rest, axial, "o-", label="at rest (run)")
    fine = np.linspace(0.0, top - z_t, 100)
    for k, style in ((best, "-"), (1 - math.sin(PHI), "--"), (1.1 * (1 - math.sin(PHI)), ":")):
        ax.plot(janssen(np.maximum(top - z_t - fine, 0.0), k, r_s, mobilised, gamma), fine, "k" + style,
                label=f"Janssen, K = {k:.2f}")
    if has_flow:
        ax.plot(p_flow, axial, "s-", label="discharge, mean")
        ax.plot(p_flow_max, axial, "^-", label="discharge, max of 0.1 s means")
    ax.set_xlabel("wall pressure p_h [Pa]")
    ax.set_ylabel("height above the transition [m]")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "silo_hopper_pressure.png"), dpi=120)


if __name__ == "__main__":
    main(sys.argv[1])
