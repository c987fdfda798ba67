"""The circular silo with a shell the sand deforms, against the same silo with rigid walls.

Reads two runs of a case with the wall maps "rest" and "flow" (cylinder) and "hopper_rest" and
"hopper_flow" (silo_hopper_closure_small.toml: its rest and discharge windows end before the
closure starts), FLEX with the elastic shell and RIGID with `rigid = true`, and prints:
- the shell's largest deflection (summary.json, and where and when in the frames) against the
  particle spacing, its largest von Mises stress and the coupling's energy error;
- per ring of the cylinder and of the hopper the wall pressure at rest (the window's mean) and in
  the discharge (the window's mean and its largest interval mean), elastic against rigid; the
  hopper's pressure is rescaled from the map's R dtheta dz to the cone's r dtheta dz / cos(beta)
  (analyse_closure.py);
- the shell's hoop force against membrane theory with the pressure the run put on it, per 50 mm
  of height, averaged over the frames of each window: N_theta = p R on the cylinder and
  N_theta = p r / cos(beta) on the cone (Timoshenko & Woinowsky-Krieger, Theory of Plates and
  Shells, ch. 14: a shell of revolution under normal pressure p has N_theta = p r2, r2 the
  second principal radius, R for the cylinder and r / cos(beta) for a cone of half-angle beta),
  and the mean radial displacement of the ring's elements.
Usage: /usr/bin/python3 cases/silo_hopper/analyse_shell.py FLEX RIGID
"""
import json
import math
import os
import sys
import tomllib

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
from analyse import metres  # noqa: E402
from analyse_closure import ring_series, window  # noqa: E402
from shell_membrane import hoop_and_meridional  # noqa: E402
from vtk.util.numpy_support import vtk_to_numpy  # noqa: E402
from vtkmodules.vtkFiltersCore import vtkPointDataToCellData  # noqa: E402
from vtk_frames import blocks, frames_of  # noqa: E402

BIN = 0.05  # m: the cylinder map's rings


def load(out):
    whole = json.load(open(os.path.join(out, "summary.json")))
    with open(whole["case_file"], "rb") as f:
        case = tomllib.load(f)
    return whole["results"], case


def ring_table(out, case, prefix, scale):
    """Ring centres, the rest window's mean, the flow window's mean and largest interval mean."""
    t, axial, p = ring_series(out, prefix + "rest")
    p = p * scale(axial)
    picked = []
    for name in ("rest", "flow"):
        start, end = window(case, prefix + name)
        picked.append(p[(t > start + 1e-9) & (t <= end + 1e-9)])
    return axial, picked[0].mean(axis=0), picked[1].mean(axis=0), picked[1].max(axis=0)


def deflection(out):
    """The largest nodal displacement over the frames: its size, height and time."""
    best = (0.0, 0.0, 0.0)
    for time, vtm in frames_of(out):
        shell = dict(blocks(vtm))["silo"]
        u = np.linalg.norm(vtk_to_numpy(shell.GetPointData().GetArray("displacement")), axis=1)
        k = int(np.argmax(u))
        if u[k] > best[0]:
            best = (u[k], shell.GetPoint(k)[2], time)
    return best


def hoop_rows(out, case, name, geo):
    """Per ring of the maps: the mean over the window's frames of the hoop force and of membrane
    theory's p r2."""
    start, end = window(case, name)
    frames = [vtm for time, vtm in frames_of(out) if start - 1e-9 <= time <= end + 1e-9]
    beta = math.radians(geo["beta"])
    z_t = (geo["R"] - geo["r0"]) / math.tan(beta)
    hoop_sum, theory_sum, radial_sum = 0.0, 0.0, 0.0
    for vtm in frames:
        shell = dict(blocks(vtm))["silo"]
        centres, hoop, _, pressure = hoop_and_meridional(shell, 2)
        r = np.hypot(centres[:, 0], centres[:, 1])
        second_radius = np.where(centres[:, 2] > z_t, r, r / math.cos(beta))
        hoop_sum = hoop_sum + hoop
        theory_sum = theory_sum + pressure * second_radius
        to_cells = vtkPointDataToCellData()
        to_cells.SetInputData(shell)
        to_cells.Update()
        u = vtk_to_numpy(to_cells.GetOutput().GetCellData().GetArray("displacement"))
        radial_sum = radial_sum + (u[:, 0] * centres[:, 0] + u[:, 1] * centres[:, 1]) / r
    z = centres[:, 2]
    # The maps' rings: the cone in 4 from the outlet, the cylinder in 50 mm from the transition.
    edges = np.concatenate([np.linspace(0.0, z_t, 5), np.arange(z_t + BIN, z.max() + BIN, BIN)])
    rows = []
    for low, high in zip(edges[:-1], edges[1:]):
        inside = (z >= low) & (z < high)
        if inside.any():
            rows.append(((low + high) / 2, "cone" if high <= z_t + 1e-9 else "cyl",
                         hoop_sum[inside].mean() / len(frames),
                         theory_sum[inside].mean() / len(frames),
                         radial_sum[inside].mean() / len(frames)))
    return rows


def main(flex, rigid):
    results, case = load(flex)
    rigid_results, _ = load(rigid)
    geo = case["fem"]["shell"][0]["geo_numbers"]
    spacing = metres(case["sph"]["body"][0]["spacing"])
    size, height, time = deflection(flex)
    largest = results["shell_largest_deflection"]["value"]
    print(f"largest deflection {largest * 1e3:.3f} mm = {largest / spacing:.3f} of the spacing "
          f"({spacing * 1e3:.0f} mm); in the frames {size * 1e3:.3f} mm at z = {height:.3f} m, "
          f"t = {time:.2f} s; largest von Mises "
          f"{results['shell_largest_von_mises']['value'] / 1e6:.2f} MPa; "
          f"coupling energy error {results['coupling_energy_error']['value']:.2e}")
    for key in ("settle_time", "sink_below_steady_rate", "wall_map_rest_normal_force",
                "wall_map_rest_shear_axial_force", "wall_map_flow_normal_force",
                "wall_map_hopper_rest_normal_force", "wall_map_hopper_flow_normal_force"):
        a, b = results[key]["value"], rigid_results[key]["value"]
        print(f"{key}: elastic {a:.4g}, rigid {b:.4g} ({a / b - 1:+.1%})")
    beta = math.radians(geo["beta"])
    map_r = metres(next(m for m in case["sph"]["wall_map"] if m["name"] == "hopper_rest")["radius"])
    z_t = metres(next(m for m in case["sph"]["wall_map"] if m["name"] == "rest")["origin"])
    cone = lambda a: map_r * math.cos(beta) / (geo["r0"] + a * math.tan(beta))  # noqa: E731
    print(" wall      z m   rest: elastic  rigid  ratio | flow mean: elastic  rigid  ratio | "
          "flow max: elastic  rigid  ratio")
    for label, prefix, scale, shift in (("hopper", "hopper_", cone, 0.0),
                                        ("cylinder", "", lambda a: np.ones_like(a), z_t)):
        e = ring_table(flex, case, prefix, scale)
        r = ring_table(rigid, case, prefix, scale)
        for j, a in enumerate(e[0]):
            if r[1][j] <= 0.0:
                continue  # above the fill
            cells = "".join(f" | {e[k][j]:8.0f} {r[k][j]:6.0f} {e[k][j] / r[k][j]:6.3f}"
                            for k in (1, 2, 3))
            print(f" {label:8s} {a + shift:5.3f}{cells}")
    for name in ("rest", "flow"):
        print(f"hoop force, mean over the frames of the {name} window: z m, part, N_theta N/m, "
              f"p r2 N/m, ratio, radial displacement um (outward +)")
        for z, part, hoop, theory, radial in hoop_rows(flex, case, name, geo):
            ratio = hoop / theory if abs(theory) > 1.0 else float("nan")
            print(f"  {z:5.3f} {part:4s} {hoop:9.1f} {theory:9.1f} {ratio:7.3f} "
                  f"{radial * 1e6:9.2f}")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
