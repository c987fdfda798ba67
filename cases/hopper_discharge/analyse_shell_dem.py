#!/usr/bin/python3
"""The DEM hopper's sheets as coupled shells (hopper_shell_dem.toml), against beam theory and
beside the continuum's sheets (hopper_shell.toml, docs/validation/hopper_discharge.md).

Usage:
    /usr/bin/python3 cases/hopper_discharge/analyse_shell_dem.py FLEX [RIGID]

FLEX is a run of the case as it stands, RIGID the same case with both interfaces rigid
(`--set 'coupling.interface[0].rigid=true' --set 'coupling.interface[1].rigid=true'`). Per run
and per metre of the slot's depth it prints the fill's mass, the steady discharge rate and, per
sheet, its normal load at rest (the grains' force on it along its outward normal at the last
output before the gate went, wall_forces.csv) and its largest value after the gate went. For
FLEX, at rest, each sheet's sag along the slope against the simply supported beam of the
sheet's bending stiffness under the pressure the run put on it (analyse_shell.beam_sag: the
frame's nodal contact_pressure averaged across the depth).
"""

import csv
import json
import os
import sys
import tomllib

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from analyse_shell import beam_sag, quantity  # noqa: E402
from vtk.util.numpy_support import vtk_to_numpy  # noqa: E402
from vtk_frames import blocks, frames_of  # noqa: E402

SHEETS = {"left": -1.0, "right": 1.0}


def sheet_geometry(case, side):
    """Slope direction, outward normal and mid-surface start of the sheet on `side` (-1: x < 0),
    its length, thickness, the depth, E and nu."""
    shell = case["fem"]["shell"][0]
    numbers = shell["geo_numbers"]
    a = np.radians(numbers["theta"])
    t = numbers["t"]
    start = np.array([side * (numbers["r0"] + t / 2 * np.cos(a)), 0.0, -t / 2 * np.sin(a)])
    steel = [m for m in case["material"] if m["name"] == shell["material"]][0]
    young = float(steel["youngs_modulus"].split()[0]) * {"GPa": 1e9, "MPa": 1e6}[
        steel["youngs_modulus"].split()[1]]
    return (np.array([side * np.sin(a), 0.0, np.cos(a)]),
            np.array([side * np.cos(a), 0.0, -np.sin(a)]), start, numbers["L"],
            quantity(shell["thickness"]), numbers["depth"], young, steel["poisson_ratio"])


def profile(vtm, geometry, side):
    """Slope coordinate s of the sheet's node rows, their mean outward displacement w and mean
    contact pressure p."""
    slope, normal, start = geometry[0], geometry[1], geometry[2]
    sheets = dict(blocks(vtm))["sheets"]
    x = vtk_to_numpy(sheets.GetPoints().GetData())
    u = vtk_to_numpy(sheets.GetPointData().GetArray("displacement"))
    p = vtk_to_numpy(sheets.GetPointData().GetArray("contact_pressure"))
    mine = np.sign(x[:, 0]) == side
    x, u, p = x[mine], u[mine], p[mine]
    s = np.round((x - u - start) @ slope, 6)
    rows = np.unique(s)
    return (rows, np.array([(u[s == r] @ normal).mean() for r in rows]),
            np.array([p[s == r].mean() for r in rows]))


def sheet_loads(out, name, geometry):
    """(time, the grains' normal load on sheet `name` in N per metre of depth) per output."""
    normal, depth = geometry[1], geometry[5]
    series = []
    with open(os.path.join(out, "wall_forces.csv")) as f:
        for row in csv.DictReader(f):
            if row["wall"] == name:
                force = np.array([float(row["force_%s_N" % c]) for c in "xyz"])
                series.append((float(row["time_s"]), force @ normal / depth))
    return series


def report(out, flex):
    summary = json.load(open(os.path.join(out, "summary.json")))
    with open(summary["case_file"], "rb") as f:
        case = tomllib.load(f)
    results = summary["results"]
    gate = [wall for wall in case["dem"]["wall"] if "remove_at" in wall][0]
    value, unit = gate["remove_at"].split()
    opened = float(value) * {"s": 1.0, "ms": 1e-3}[unit]
    depth = sheet_geometry(case, 1.0)[5]
    print("%s (%s sheets): fill %.1f kg/m, steady rate %.1f kg/m/s, gate gone at %.2f s"
          % (out, "elastic" if flex else "rigid", results["initial_mass"]["value"] / depth,
             results["sink_outlet_steady_rate"]["value"] / depth, opened))
    rests = {}
    for name, side in SHEETS.items():
        geometry = sheet_geometry(case, side)
        series = sheet_loads(out, name, geometry)
        rest = [row for row in series if row[0] < opened - 1e-9][-1]
        flow = max((row for row in series if row[0] > opened + 1e-9), key=lambda row: row[1])
        rests[name] = rest[1]
        print("  %s: normal load at rest (%.2f s) %.0f N/m, largest after opening %.0f N/m at "
              "%.2f s (%.2f of rest)" % (name, rest[0], rest[1], flow[1], flow[0],
                                         flow[1] / rest[1]))
        if not flex:
            continue
        young, nu, thickness = geometry[6], geometry[7], geometry[4]
        stiffness = young * thickness**3 / (12.0 * (1.0 - nu**2))
        vtm = dict((round(t, 6), v) for t, v in frames_of(out))[round(rest[0], 6)]
        s, w, p = profile(vtm, geometry, side)
        fine, sag, moment = beam_sag(s, p, stiffness)
        beam = np.interp(s, fine, sag)
        at = int(np.argmax(w))
        print("    at rest: largest sag %.2f mm at s = %.2f m; the beam under the run's pressure "
              "%.2f mm (sheet / beam %.3f); largest moment %.0f N m/m, 6 M / t^2 = %.1f MPa"
              % (1e3 * w[at], s[at], 1e3 * beam.max(), w[at] / beam.max(), moment.max(),
                 6e-6 * moment.max() / thickness**2))
    if flex:
        print("  shell: largest deflection %.2f mm, largest von Mises %.1f MPa over the run"
              % (1e3 * results["shell_largest_deflection"]["value"],
                 1e-6 * results["shell_largest_von_mises"]["value"]))
    return results["sink_outlet_steady_rate"]["value"], rests


def main(argv):
    if not argv:
        print(__doc__)
        return 2
    flex_rate, flex_rests = report(argv[0], True)
    if len(argv) > 1:
        rigid_rate, rigid_rests = report(argv[1], False)
        print("elastic / rigid: steady rate %.3f, sheets' load at rest %.3f (left) %.3f (right)"
              % (flex_rate / rigid_rate, flex_rests["left"] / rigid_rests["left"],
                 flex_rests["right"] / rigid_rests["right"]))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
