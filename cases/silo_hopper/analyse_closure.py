"""The circular silo's sudden closure (silo_hopper_closure_small.toml): the wall pressure per ring
of the cylinder and of the hopper at rest, in the discharge and through the closure, the peak and
where it occurs, against the bound rest + rho c v.

Reads OUT (a run of a case with the wall maps "rest", "flow", "closure" on the cylinder and
"hopper_rest", "hopper_flow", "hopper_closure" on the hopper) and prints per ring (the mean over
the map's sectors of each output interval's mean, 20 ms in the case):
- the mean at rest, the largest interval mean in the discharge, the largest interval mean in the
  closure window with the time its interval ends, the closure window's mean, and their ratios;
- the bound of an elastic column's arrest (Joukowsky): stopping sand that moves down at v raises
  its stress by at most rho c v, c the P-wave speed of the elastic sand, and the wall's share of
  that is at most all of it (docs/validation/silo.md, "Sudden closure"). v(z) = W / (rho A(z)),
  W the quarter's steady rate (summary.json), A the quarter's cross-section at the ring's height
  (pi R^2 / 4 in the cylinder, pi r(z)^2 / 4 in the hopper, r(z) = r0 + z tan(beta));
- the mass audit: the discharged mass when the gate stops, at the end, and when the last particle
  left; the sand's weight against the walls' vertical load at rest and at the end.
The hopper is mapped with a cylinder map about the axis, whose cells have the area R dtheta dz of
the map's radius R; the cone's cell has r(z) dtheta dz / cos(beta), so its pressure is the map's
times R cos(beta) / r(z) at the ring's centre.
Usage: /usr/bin/python3 cases/silo_hopper/analyse_closure.py OUT
"""
import csv
import glob
import json
import math
import os
import sys
import tomllib

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from analyse import metres  # noqa: E402

RHO, G, YOUNG, POISSON = 1600.0, 9.81, 5e6, 0.3  # the case's sand
P_MODULUS = YOUNG * (1 - POISSON) / ((1 + POISSON) * (1 - 2 * POISSON))
WAVE_SPEED = math.sqrt(P_MODULUS / RHO)


def ring_series(out, name):
    """Times (interval ends), ring centres and the ring means (over the sectors) of every output
    interval of map NAME: arrays t[i], axial[j], p[i, j]."""
    times, rows = [], []
    for path in sorted(glob.glob(os.path.join(out, "wall_maps", f"{name}_[0-9]*.csv"))):
        rings = {}
        with open(path) as f:
            for row in csv.DictReader(f):
                time = float(row["time_s"])
                rings.setdefault(float(row["axial_m"]), []).append(float(row["pressure_Pa"]))
        axial = np.array(sorted(rings))
        times.append(time)
        rows.append([np.mean(rings[a]) for a in axial])
    return np.array(times), axial, np.array(rows)


def window(case, name):
    table = next(m for m in case["sph"]["wall_map"] if m["name"] == name)
    start, end, _ = table["window"].split()
    return float(start), float(end)


def wall_rows(out, case, prefix, height, radius, scale):
    """One printed row per ring of the wall whose maps are PREFIX + rest/flow/closure."""
    t, axial, p = ring_series(out, prefix + "rest")
    p = p * scale(axial)
    pick = {w: (t > window(case, prefix + w)[0] + 1e-9) & (t <= window(case, prefix + w)[1] + 1e-9)
            for w in ("rest", "flow", "closure")}
    rate = json.load(open(os.path.join(out, "summary.json")))["results"]
    rate = rate["sink_below_steady_rate"]["value"]
    rows = []
    for j, a in enumerate(axial):
        rest = p[pick["rest"], j].mean()
        flow_max = p[pick["flow"], j].max()
        closure = p[pick["closure"], j]
        k = int(np.argmax(closure))
        v = rate / (RHO * math.pi * radius(height(a)) ** 2 / 4)
        rows.append((height(a), rest, flow_max, closure[k], t[pick["closure"]][k],
                     closure.mean(), rest + RHO * WAVE_SPEED * v))
    return rows


def main(out):
    whole = json.load(open(os.path.join(out, "summary.json")))
    with open(whole["case_file"], "rb") as f:
        case = tomllib.load(f)
    geo = case["fem"]["shell"][0]["geo_numbers"]
    r0, beta, wall_r = geo["r0"], math.radians(geo["beta"]), geo["R"]
    z_t = metres(next(m for m in case["sph"]["wall_map"] if m["name"] == "rest")["origin"])
    map_r = metres(next(m for m in case["sph"]["wall_map"] if m["name"] == "hopper_rest")["radius"])
    cone_r = lambda z: r0 + z * math.tan(beta)  # noqa: E731
    print(f"P-wave speed c = {WAVE_SPEED:.1f} m/s; z above the outlet's plane, transition at "
          f"{z_t:.4f} m")
    print(" wall      z m   rest Pa  flow max  closure max (at s)  closure mean  max/rest  "
          "max/flow  rest + rho c v")
    peak = (0.0, "", 0.0, 0.0)
    for label, rows in (
            ("hopper", wall_rows(out, case, "hopper_", lambda a: a, cone_r,
                                 lambda a: map_r * math.cos(beta) / cone_r(a))),
            ("cylinder", wall_rows(out, case, "", lambda a: z_t + a, lambda z: wall_r,
                                   lambda a: np.ones_like(a)))):
        for z, rest, flow, top, when, mean, bound in rows:
            if rest <= 0.0:
                continue  # above the fill
            print(f" {label:8s} {z:5.3f} {rest:8.0f} {flow:9.0f} {top:12.0f} ({when:.2f}) "
                  f"{mean:13.0f} {top / rest:9.2f} {top / flow:9.2f} {bound:14.0f}")
            peak = max(peak, (top, label, z, when))
    print(f"closure peak: {peak[0]:.0f} Pa on the {peak[1]}, ring at z = {peak[2]:.3f} m, in the "
          f"interval ending at {peak[3]:.2f} s")
    books(out, whole["results"])


def books(out, results):
    """The discharged mass through the closure and the weight the walls carry."""
    rows = list(csv.DictReader(open(os.path.join(out, "discharge.csv"))))
    mass = [(float(r["time_s"]), float(r["discharged_mass_kg"])) for r in rows]
    last_change = max(t for (t, m), (_, before) in zip(mass[1:], mass[:-1]) if m != before)
    print(f"discharged: {mass[-1][1]:.4f} kg at the end ({mass[-1][0]:.2f} s), the last particle "
          f"out by {last_change:.2f} s; mass audit {results['mass_audit_error']['value']:.1e}")
    loads = {}
    for r in csv.DictReader(open(os.path.join(out, "wall_forces.csv"))):
        loads.setdefault(float(r["time_s"]), 0.0)
        loads[float(r["time_s"])] += float(r["force_z_N"])
    end = max(loads)
    weight = results["scene_mass"]["value"] * G
    print(f"at the end ({end:.2f} s): walls carry {-loads[end]:.2f} N, the sand's weight "
          f"{weight:.2f} N ({-loads[end] / weight - 1:+.2e})")


if __name__ == "__main__":
    main(sys.argv[1])
