#!/usr/bin/python3
"""The plane-wedge hopper's sheet as a coupled shell (hopper_shell*.toml), against beam theory
and against the same run with the sheet rigid.

Usage:
    /usr/bin/python3 cases/hopper_discharge/analyse_shell.py FLEX [RIGID]

FLEX is a run of the case as it stands (the elastic sheet), RIGID the same case with
`--set 'coupling.interface[0].rigid=true'`. Per run it prints, per metre of slot (the strip is
the half x > 0 of a slot `depth` deep: figures times 2 / depth):
  * the fill's mass, the settle time (the gate goes then), the steady discharge rate;
  * the sheet's normal load at rest (the sand's force on it along its normal at the last
    output before the gate went, wall_forces.csv) and its largest value in the discharge, with
    when it occurred.
For FLEX, at rest and at the discharge's largest load, the sheet's sag along the slope against
a simply supported beam of the strip's bending stiffness D = E t^3 / (12 (1 - nu^2))
(cylindrical bending: Timoshenko & Woinowsky-Krieger 1959, section 1) under the normal
pressure the run put on the sheet (the frame's nodal contact_pressure, averaged across the
strip): M(s) from statics, w'' = -M / D twice integrated with w = 0 at both supports. The
friction traction acts at the face, t/2 off the mid-surface: its moment, tau t / 2, is below
1 % of the bending moment and left out.
"""

import csv
import json
import os
import sys
import tomllib

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
from vtk.util.numpy_support import vtk_to_numpy  # noqa: E402
from vtk_frames import blocks, frames_of  # noqa: E402


def quantity(text):
    """The number of a case-file quantity in the units it is written in mm or m, as metres."""
    value, unit = text.split()
    return float(value) * {"mm": 1e-3, "m": 1.0}[unit]


def load(out):
    summary = json.load(open(os.path.join(out, "summary.json")))
    with open(summary["case_file"], "rb") as f:
        case = tomllib.load(f)
    return summary["results"], case


def sheet_geometry(case):
    """Slope direction, outward normal, the mid-surface's start, length, thickness, depth, E, nu."""
    shell = case["fem"]["shell"][0]
    numbers = shell["geo_numbers"]
    a = np.radians(numbers["theta"])
    t = numbers["t"]
    start = np.array([numbers["r0"] + t / 2 * np.cos(a), 0.0, -t / 2 * np.sin(a)])
    steel = [m for m in case["material"] if m["name"] == shell["material"]][0]
    young = float(steel["youngs_modulus"].split()[0]) * {"GPa": 1e9, "MPa": 1e6}[
        steel["youngs_modulus"].split()[1]]
    return (np.array([np.sin(a), 0.0, np.cos(a)]), np.array([np.cos(a), 0.0, -np.sin(a)]),
            start, numbers["L"], quantity(shell["thickness"]), numbers["depth"], young,
            steel["poisson_ratio"])


def profile(vtm, geometry):
    """Slope coordinate s of the sheet's node rows, their mean outward displacement w and mean
    contact pressure p."""
    slope, normal, start = geometry[0], geometry[1], geometry[2]
    sheet = dict(blocks(vtm))["sheet"]
    x = vtk_to_numpy(sheet.GetPoints().GetData())
    u = vtk_to_numpy(sheet.GetPointData().GetArray("displacement"))
    p = vtk_to_numpy(sheet.GetPointData().GetArray("contact_pressure"))
    s = np.round((x - u - start) @ slope, 6)
    rows = np.unique(s)
    return (rows, np.array([(u[s == r] @ normal).mean() for r in rows]),
            np.array([p[s == r].mean() for r in rows]))


def beam_sag(s, p, stiffness):
    """Sag of a simply supported beam (supports at s[0] and s[-1]) under p(s), linear between
    the points: w'' = -M / D, M from statics."""
    fine = np.linspace(s[0], s[-1], 2001)
    q = np.interp(fine, s, p)
    span = fine[-1] - fine[0]
    ds = fine[1] - fine[0]
    force = np.concatenate(([0.0], np.cumsum((q[1:] + q[:-1]) / 2 * ds)))
    first = np.concatenate(([0.0], np.cumsum((q[1:] * fine[1:] + q[:-1] * fine[:-1]) / 2 * ds)))
    reaction = (force[-1] * fine[-1] - first[-1]) / span  # moments about the far support
    moment = reaction * (fine - fine[0]) - (fine * force - first)
    slope = np.concatenate(([0.0], np.cumsum((moment[1:] + moment[:-1]) / 2 * ds))) / -stiffness
    sag = np.concatenate(([0.0], np.cumsum((slope[1:] + slope[:-1]) / 2 * ds)))
    sag -= (fine - fine[0]) / span * sag[-1]
    return fine, sag, moment


def sheet_load(out, geometry):
    """(time, normal load on the sheet in N per metre of the strip's depth, frame) at every
    output instant: the sand's force on the sheet (wall_forces.csv, rigid or elastic alike)
    along the outward normal."""
    normal, depth = geometry[1], geometry[5]
    frames = {round(time, 6): vtm for time, vtm in frames_of(out)}
    series = []
    with open(os.path.join(out, "wall_forces.csv")) as f:
        for row in csv.DictReader(f):
            if row["wall"] != "sheet":
                continue
            force = np.array([float(row["force_%s_N" % c]) for c in "xyz"])
            time = float(row["time_s"])
            series.append((time, force @ normal / depth, frames.get(round(time, 6))))
    return series


def report(out, flex):
    results, case = load(out)
    geometry = sheet_geometry(case)
    depth = geometry[5]
    per_metre = 2.0 / depth
    mass = results["initial_mass"]["value"] + results.get("created_mass", {}).get("value", 0.0)
    opened = results["settle_time"]["value"]
    rate = results["sink_below_steady_rate"]["value"]
    series = sheet_load(out, geometry)
    rest = [row for row in series if row[0] < opened - 1e-9][-1]
    flow = max((row for row in series if row[0] > opened + 1e-9), key=lambda row: row[1])
    print("%s (%s): fill %.1f kg/m, gate gone at %.4f s, steady rate %.1f kg/m/s (window "
          "%.2f-%.2f s); sheet's normal load at rest (%.2f s) %.0f N/m, largest in the discharge "
          "%.0f N/m at %.2f s (%.2f of rest); energy_balance_error %.2e"
          % (out, "elastic sheet" if flex else "rigid sheet", mass * per_metre, opened,
             rate * per_metre, results["sink_below_steady_window_start"]["value"],
             results["sink_below_steady_window_end"]["value"], rest[0], rest[1], flow[1],
             flow[0], flow[1] / rest[1], results["energy_balance_error"]["value"]))
    if flex:
        young, nu, thickness = geometry[6], geometry[7], geometry[4]
        stiffness = young * thickness**3 / (12.0 * (1.0 - nu**2))
        print("  shell: largest deflection %.2f mm, largest von Mises %.1f MPa, coupling energy "
              "error %.2e" % (1e3 * results["shell_largest_deflection"]["value"],
                              1e-6 * results["shell_largest_von_mises"]["value"],
                              results["coupling_energy_error"]["value"]))
        # The beam check reads the frames' pressure (the window's mean load, which the static
        # shell answered): at rest, and at the discharge frame where its resultant is largest.
        loaded = []
        for time, vtm in frames_of(out):
            if time > opened + 1e-9:
                s, _, p = profile(vtm, geometry)
                loaded.append((time, np.trapz(p, s), vtm))
        for label, row in (("rest", rest), ("discharge peak", max(loaded, key=lambda r: r[1]))):
            s, w, p = profile(row[2], geometry)
            fine, sag, moment = beam_sag(s, p, stiffness)
            at = int(np.argmax(w))
            beam = np.interp(s, fine, sag)
            print("  %s (%.2f s): sheet's largest sag %.2f mm at s = %.2f m; the beam under the "
                  "run's pressure %.2f mm at s = %.2f m (sheet / beam %.3f); largest moment "
                  "%.0f N m/m, bending stress 6 M / t^2 = %.1f MPa"
                  % (label, row[0], 1e3 * w[at], s[at], 1e3 * beam.max(), s[int(np.argmax(beam))],
                     w[at] / beam.max(), moment.max(), 6e-6 * moment.max() / thickness**2))
    return rate * per_metre, rest[1]


def main(argv):
    if not argv:
        print(__doc__)
        return 2
    flex_rate, flex_rest = report(argv[0], True)
    if len(argv) > 1:
        rigid_rate, rigid_rest = report(argv[1], False)
        print("elastic / rigid: steady rate %.3f, sheet's load at rest %.3f"
              % (flex_rate / rigid_rate, flex_rest / rigid_rest))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
