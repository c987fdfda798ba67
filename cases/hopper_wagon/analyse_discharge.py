#!/usr/bin/python3
"""Figures of a hopper-wagon discharge run (cases/hopper_wagon/hopper_wagon.toml).

Usage:
    /usr/bin/python3 cases/hopper_wagon/analyse_discharge.py OUT [OUT2 ...] [--png FILE]
                     [--labels A,B] [--open T] [--door H]

For every run directory OUT it reads summary.json, discharge.csv, wall_forces.csv and the
frames (VTK's Python bindings, python3-vtk9) and prints, and writes to OUT/wagon_figures.json:
  * what it read from the run itself: the case file summary.json names (case_file) with the
    run's --set overrides, and from it the door wall's opening time (the last instant of its
    velocity history before it moves, after history_start, a phase's start read from
    summary.json's phases) and its height as drawn (the length of its edge_v); --open and --door
    replace them;
  * the discharged mass against time (both sinks: the doorway and the ground) and the time the
    discharge ends (the last output interval that still discharged);
  * the residue: the load's mass left in the scene at the end (summary.json's scene_mass), the
    part of it still in flight (through the door or below the sill, not yet at a sink) and the
    part in the body, and where that stays: particles
    within 2.5 spacings of a surface are "on" it (saddle slope sheet, middle or end slope
    sheet, side wall, end wall), those near two surfaces are "on an edge" (the hips, the
    body's corners), the rest rest on other particles;
  * the door: its resultant (normal component, N) and, with the moment about the hinge line
    (wall_forces.csv gives the moment about the wall centre, which the case puts on the hinge
    line), the lock reaction at the sill, R_sill = M / H, and the hinge reaction,
    R_hinge = F - R_sill (statics of a door hinged at its top and locked at its sill), at
    rest before the door opens and their peaks;
  * the shell (an elastic body; a rigid one carries its own weight only): the largest von Mises stress
    (of the top, middle and bottom surfaces) per frame, its place and part, while settling
    (before --open) and during the discharge.
With --png FILE it plots the discharged mass of every run against time.
"""

import argparse
import csv
import json
import os
import re
import sys
import tomllib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402

# The frame readers shared with scripts/render_frames.py.
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
from vtk_frames import blocks, frames_of  # noqa: E402

# Geometry of hopper_wagon.geo (cases/hopper_wagon/README.md), m.
TAN = np.tan(np.radians(49.0))
Z_RIDGE, X_MID, X_END, Z_SILL, HALF_WIDTH, HALF_LENGTH = 0.9 + 1.5 * TAN, 0.35, 5.78, 0.9, 1.5, 6.33
DENSITY = 2099.0  # the load's, kg/m^3
NEAR_SPACINGS = 2.5  # "on" a surface: within the contact potential's reach (2h = 2.6 dp) and a bit


UNITS = {"s": 1.0, "ms": 1e-3, "m": 1.0, "mm": 1e-3, "cm": 1e-2}


def numbers(text):
    """The numbers of a quantity text ("1.5 s", "0 0 1220 mm") in SI (times and lengths)."""
    tokens = text.split()
    return [float(t) * UNITS.get(tokens[-1], 1.0) for t in tokens[:-1]]


def override_value(text):
    """A --set value as the CLI reads it: TOML when it parses, a string otherwise."""
    try:
        return tomllib.loads("v = " + text)["v"]
    except tomllib.TOMLDecodeError:
        return text


def run_case(summary, out):
    """The case as the run read it: the file summary.json names, with the run's --set overrides
    ("sph.wall[2].angular_velocity_history=[...]") applied."""
    path = summary["case_file"]
    if not os.path.exists(path):
        path = os.path.join(out, path)  # a relative path from where the run was started
    with open(path, "rb") as f:
        case = tomllib.load(f)
    for override in summary.get("overrides", []):
        key, _, text = override.partition("=")
        steps = re.findall(r"(\w+)(?:\[(\d+)\])?", key)
        node = case
        for k, (name, index) in enumerate(steps):
            last = k == len(steps) - 1
            if index:
                if last:
                    node[name][int(index)] = override_value(text)
                else:
                    node = node[name][int(index)]
            elif last:
                node[name] = override_value(text)
            else:
                node = node.setdefault(name, {})
    return case


def door_of_run(summary, out, name="door"):
    """The door wall's opening time (s) and drawn height (m), from the run's case: the history
    holds the door still until its last zero sample before the first non-zero one, and counts
    from history_start (a time, or a phase whose start summary.json lists)."""
    case = run_case(summary, out)
    wall = next(w for w in case["sph"]["wall"] if w["name"] == name)
    history = wall.get("angular_velocity_history") or wall.get("velocity_history") or []
    start = 0.0
    begin = wall.get("history_start", "0 s")
    if begin.startswith("phase:"):
        start = next(p["start"] for p in summary["phases"] if p["name"] == begin[len("phase:"):])
    else:
        start = numbers(begin)[0]
    opens, still = None, None
    for time, velocity in history:
        if any(v != 0.0 for v in numbers(velocity)):
            opens = start + (still if still is not None else numbers(time)[0])
            break
        still = numbers(time)[0]
    return opens, float(np.linalg.norm(numbers(wall["edge_v"])))


def rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def surface_distances(x):
    """Distance of each point to the body's load-bearing surfaces (inside the body)."""
    n = np.sqrt(1.0 + TAN**2)
    return {
        "saddle slope sheets": (x[:, 2] + TAN * x[:, 1] - Z_RIDGE) / n,
        "middle slope sheet": (x[:, 2] - Z_SILL + TAN * (x[:, 0] - X_MID)) / n,
        "end slope sheet": (x[:, 2] - Z_SILL - TAN * (x[:, 0] - X_END)) / n,
        "side wall": HALF_WIDTH - x[:, 1],
        "end wall": HALF_LENGTH - x[:, 0],
    }


def residue(out, scene_mass):
    """The load left in the scene (the run's scene_mass), split into what is in the body and
    what is still in flight, and where the body's part stays. Each particle's mass, and from it
    the spacing, is the scene's mass over the particles of the last frame (the run's spacing,
    whatever the case set)."""
    time, vtm = frames_of(out)[-1]
    load = dict(blocks(vtm))["load"]
    if load is None or load.GetNumberOfPoints() == 0:
        return {"time_s": time, "mass_kg": scene_mass, "in_body_kg": 0.0, "in_flight_kg": 0.0,
                "places_kg": {}}
    x = vtk_to_numpy(load.GetPoints().GetData())
    mass_each = scene_mass / len(x)
    near_distance = NEAR_SPACINGS * (mass_each / DENSITY) ** (1.0 / 3.0)
    inside = (x[:, 1] < HALF_WIDTH) & (x[:, 0] < HALF_LENGTH) & (x[:, 2] > Z_SILL - 0.3)
    near = {k: (d < near_distance)[inside] for k, d in surface_distances(x).items()}
    count = np.sum(list(near.values()), axis=0)
    places = {"on an edge (two surfaces)": int(np.sum(count >= 2)),
              "on other particles": int(np.sum(count == 0))}
    for name, flag in near.items():
        places["on the " + name] = int(np.sum(flag & (count == 1)))
    return {"time_s": time, "mass_kg": scene_mass,
            "in_body_kg": float(np.sum(inside)) * mass_each,
            "in_flight_kg": float(np.sum(~inside)) * mass_each,
            "particles": int(np.sum(inside)),
            "places_kg": {k: v * mass_each for k, v in places.items() if v}}


def door(out, opens, height):
    history = [r for r in rows(os.path.join(out, "wall_forces.csv")) if r["wall"] == "door"]
    t = np.array([float(r["time_s"]) for r in history])
    force = np.array([float(r["force_y_N"]) for r in history])  # the load pushes it outward, +y
    moment = np.abs(np.array([float(r["moment_x_Nm"]) for r in history]))
    sill = moment / height
    hinge = force - sill
    rest = np.searchsorted(t, opens) - 1
    return {"at_rest_time_s": float(t[rest]), "force_N": float(force[rest]),
            "sill_lock_N": float(sill[rest]), "hinge_N": float(hinge[rest]),
            "peak_force_N": float(force.max()), "peak_force_time_s": float(t[np.argmax(force)]),
            "peak_hinge_N": float(hinge.max()), "peak_sill_lock_N": float(sill.max())}


def shell_peaks(out, opens):
    peaks = {"settling": None, "discharge": None}
    for time, vtm in frames_of(out):
        shell = dict(blocks(vtm)).get("wagon")
        cells = shell.GetCellData() if shell is not None else None
        if cells is None or cells.GetArray("von_mises_top") is None:
            return peaks
        stress = np.max([vtk_to_numpy(cells.GetArray("von_mises_" + s)) for s in ("top", "middle", "bottom")], axis=0)
        cell = int(np.argmax(stress))
        ids = shell.GetCell(cell).GetPointIds()
        centre = np.mean([shell.GetPoint(ids.GetId(k)) for k in range(ids.GetNumberOfIds())], axis=0)
        phase = "settling" if time < opens else "discharge"
        if peaks[phase] is None or stress[cell] > peaks[phase]["von_mises_MPa"] * 1e6:
            plastic = vtk_to_numpy(cells.GetArray("plastic_strain"))
            peaks[phase] = {"von_mises_MPa": float(stress[cell]) / 1e6, "time_s": time,
                            "at_m": [round(float(c), 3) for c in centre],
                            "thickness_mm": float(vtk_to_numpy(cells.GetArray("thickness"))[cell]) * 1e3,
                            "largest_plastic_strain": float(np.max(plastic))}
    return peaks


def discharge(out):
    curve = {}
    for r in rows(os.path.join(out, "discharge.csv")):
        t = float(r["time_s"])
        curve[t] = curve.get(t, 0.0) + float(r["discharged_mass_kg"])
    times = sorted(curve)
    mass = [curve[t] for t in times]
    ends = next((times[i] for i in range(len(times) - 1, 0, -1) if mass[i] > mass[i - 1]), None)
    return times, mass, ends


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("outs", nargs="+")
    parser.add_argument("--png")
    parser.add_argument("--labels", help="comma-separated legend labels, one per run")
    parser.add_argument("--open", type=float,
                        help="the door starts opening [s] (default: from the run's case)")
    parser.add_argument("--door", type=float,
                        help="door opening height as drawn [m] (default: from the run's case)")
    args = parser.parse_args()
    labels = args.labels.split(",") if args.labels else args.outs
    for out, label in zip(args.outs, labels):
        summary = json.load(open(os.path.join(out, "summary.json")))
        results = summary["results"]
        created = results["initial_mass"]["value"] + results["created_mass"]["value"]
        times, mass, ends = discharge(out)
        opens, height = door_of_run(summary, out)
        opens = args.open if args.open is not None else opens
        height = args.door if args.door is not None else height
        figures = {
            "case": summary["case"], "status": summary["status"],
            "wall_time_s": summary["wall_time_s"], "simulated_time_s": summary["simulated_time_s"],
            "load_kg": created, "discharged_kg": mass[-1], "discharge_ends_s": ends,
            "mass_audit_error": results["mass_audit_error"]["value"],
            "residue": residue(out, results["scene_mass"]["value"]),
            "door_opens_s": opens, "door_height_m": height,
            "door": door(out, opens, height),
            # A rigid body (`rigid = true`) carries its own weight only: no stresses to report.
            "shell": (shell_peaks(out, opens)
                      if summary["model"].get("wall body") != "rigid" else "rigid body"),
        }
        with open(os.path.join(out, "wagon_figures.json"), "w") as f:
            json.dump(figures, f, indent=2)
        print(json.dumps(figures, indent=2))
        if args.png:
            plt.plot(times, np.array(mass) / 1e3, label=label)
    if args.png:
        plt.xlabel("time [s]")
        plt.ylabel("discharged mass, quarter wagon [t]")
        plt.axvline(opens, color="grey", linestyle=":", label="door opens")
        plt.legend()
        plt.grid(True, alpha=0.3)
        plt.savefig(args.png, dpi=120, bbox_inches="tight")


if __name__ == "__main__":
    main()
