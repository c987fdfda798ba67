#!/usr/bin/python3
"""How the start gap between a body (or a source's sites) and a wall decides how a run starts.

Usage:
    /usr/bin/python3 scripts/start_gap_sweep.py GRAINLOAD OUT_DIR [--series NAME,...]
        [--jobs 2] [--end 0.1]

Each series places a block of sand in a bin (plane strain: 10 mm particles, a box wall of three
10 mm layers outside its inner faces 202 mm apart; 3D: a 122 mm square bin) with its outer
particles at a gap g from the first wall layer, runs it for END seconds with and without gravity,
and writes OUT_DIR/start_gap_sweep.csv and a Markdown table on standard output:

  g         the smallest centre distance from a body particle (or source site) to a wall particle,
            also in units of the contact reach 2h (h = 1.3 spacings) and of the spacing;
  E0        the energy the contact potential stores at t = 0, thesis eq. (5.3.12) integrated:
            U = K V_i V_j W(dp) u^n / n, u = W(r)/W(dp), summed over body-wall pairs; computed
            here from the first frame's particle positions;
  E0/Mgs    E0 over the body's weight times one spacing (M g s), where M is the body's mass (a
            source: of all its sites filled);
  status    of the gravity run: "done", or "unstable at t";
  KE_push   the peak kinetic energy over the first END seconds with gravity off (all of it the
            contact's push), over M g s;
  KE_g      the peak kinetic energy with gravity, over M g s (a start at 2h falls onto the
            potential: about M g times the distance to where it balances the weight).

Series (2D unless named 3D): floor (the gap under the block), side (beside it, floor at 2h),
stiff (floor gap at a contact stiffness 10 times E), tall (floor gap, a block 3 times taller),
fine (floor gap, walls at half the spacing in six layers), source (a source box beside the wall
filling a seed row), floor3d. A run that grainload refuses before it starts (exit 2) is listed as
"refused".
"""

import argparse
import concurrent.futures
import csv
import json
import math
import os
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import vtk_frames  # noqa: E402
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402

SPACING = 0.010
H_RATIO = 1.3
REACH = 2.0 * H_RATIO * SPACING
DENSITY = 1500.0
GRAVITY = 9.81

# Gaps in spacings from just outside the overlap refusal (0.9 spacing) to the reach 2.6.
GAPS = [1.0, 1.2, 1.4, 1.5, 1.6, 1.8, 1.9, 2.0, 2.1, 2.2, 2.3, 2.4, 2.5, 2.6]

MATERIAL = """
[[material]]
name = "sand"
model = "drucker_prager"
density = "1500 kg/m^3"
youngs_modulus = "5 MPa"
poisson_ratio = 0.3
friction_angle = "30 deg"
cohesion = "0 Pa"
dilatancy_angle = "0 deg"
cone_fit = "{cone}"
"""


def scene(series, gap_mm, gravity, end):
    """The case text of one run: the block's outer particles gap_mm from the first layer."""
    three_d = series.endswith("3d")
    dimension = 3 if three_d else 2
    g = f"0 0 -{GRAVITY} m/s^2" if three_d else f"0 -{GRAVITY} m/s^2"
    stiffness = "50 MPa" if series == "stiff" else "5 MPa"
    # The first layer lies half a wall spacing outside an inner face, the first particle centre
    # half a spacing inside the body's box: box edge = gap - one spacing from the face.
    edge = gap_mm - 10.0
    clear = 16.0  # 26 mm = 2h from the first layer
    # Walls at half the spacing: first layer 2.5 mm outside the face, 6 layers fill the reach.
    wall_keys = 'spacing = "5 mm"\nlayers = 6\n' if series == "fine" else ""
    if series == "fine":
        edge = gap_mm - 7.5
        clear = 18.5
    text = f"""[case]
dimension = {dimension}
end_time = "{end} s"
output_interval = "0.002 s"
gravity = "{g if gravity else ('0 0 0 m/s^2' if three_d else '0 0 m/s^2')}"
{MATERIAL.format(cone="compression" if three_d else "plane_strain")}
[sph.contact]
stiffness = "{stiffness}"
damping_ratio = 0.5
"""
    if three_d:
        text += """
[[sph.wall]]
name = "bin"
type = "box"
min = "0 0 0 mm"
max = "132 132 300 mm"
open_top = true
"""
        body = f'min = "{clear} {clear} {edge} mm"\nmax = "106 106 {edge + 60.0} mm"'
    else:
        text += """
[[sph.wall]]
name = "bin"
type = "box"
min = "0 0 mm"
max = "212 300 mm"
""" + wall_keys
        height = 300.0 if series == "tall" else 100.0
        if series == "side":
            body = f'min = "{edge} {clear} mm"\nmax = "186 {clear + height} mm"'
        elif series == "source":
            body = f'min = "{clear} {clear} mm"\nmax = "186 {clear + 10.0} mm"'
        else:
            body = f'min = "{clear} {edge} mm"\nmax = "186 {edge + height} mm"'
    text += f"""
[[sph.body]]
name = "fill"
material = "sand"
spacing = "10 mm"

[sph.body.shape]
type = "box"
{body}
"""
    if series == "source":
        text += f"""
[[sph.source]]
name = "top"
body = "fill"
min = "{edge} {clear + 10.0} mm"
max = "186 {clear + 110.0} mm"
mass_rate = "1000 kg/m/s"
"""
    return text


def kernel(r, h, dimension):
    """Cubic spline W(r), thesis eq. (4.3.1.18)."""
    q = r / h
    alpha = (15.0 / (7.0 * math.pi) if dimension == 2 else 3.0 / (2.0 * math.pi)) / h**dimension
    inner = 2.0 / 3.0 - q * q + 0.5 * q**3
    outer = np.where(q < 2.0, (2.0 - q) ** 3 / 6.0, 0.0)
    return alpha * np.where(q < 1.0, inner, outer)


def block(vtm, name):
    for block_name, data in vtk_frames.blocks(vtm):
        if block_name == name and data is not None:
            points = vtk_to_numpy(data.GetPoints().GetData())
            velocity = vtk_to_numpy(data.GetPointData().GetArray("velocity"))
            return points, velocity
    return np.zeros((0, 3)), np.zeros((0, 3))


def start_contact(points, wall, dimension, stiffness, wall_spacing):
    """Nearest gap, E0 of the points against the wall particles."""
    h = H_RATIO * SPACING
    volume = SPACING**dimension * wall_spacing**dimension
    w_ref = kernel(SPACING, h, dimension)
    gap = math.inf
    energy = 0.0
    for x in points:
        r = np.linalg.norm(wall - x, axis=1)
        gap = min(gap, r.min())
        u = kernel(r[r < 2.0 * h], h, dimension) / w_ref
        energy += float(np.sum(stiffness * volume * w_ref * u))
    return gap, energy


def run(grainload, folder, text):
    os.makedirs(folder, exist_ok=True)
    case = os.path.join(folder, "case.toml")
    with open(case, "w") as f:
        f.write(text)
    out = os.path.join(folder, "out")
    code = subprocess.run([grainload, "run", case, "--out", out, "--threads", "1"],
                          stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                          check=False).returncode
    if code == 2:
        return None
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    frames = vtk_frames.frames_of(out)
    peak = 0.0
    for _, vtm in frames:
        _, v = block(vtm, "fill")
        peak = max(peak, float(np.sum(v * v)))
    first_points, _ = block(frames[0][1], "fill")
    wall, _ = block(frames[0][1], "wall_bin")
    return summary, peak, first_points, wall


def one(grainload, out_dir, series, gap, end):
    three_d = series.endswith("3d")
    dimension = 3 if three_d else 2
    gap_mm = gap * SPACING * 1000.0
    stiffness = 50e6 if series == "stiff" else 5e6
    wall_spacing = SPACING / 2.0 if series == "fine" else SPACING
    mass_particle = DENSITY * SPACING**dimension
    row = {"series": series, "gap_spacings_set": gap}
    results = {}
    for gravity in (True, False):
        folder = os.path.join(out_dir, f"{series}_{gap:.2f}_{'g' if gravity else 'nog'}")
        results[gravity] = run(grainload, folder, scene(series, gap_mm, gravity, end))
    # Without gravity nothing is refused (the check's reference is the weight): the positions
    # at t = 0 come from that run.
    _, peak_push, points, wall = results[False]
    if series == "source":
        # The sites of the source box, not its particles: the cells of its lattice that lie
        # wholly inside it (SourceSet::lattice), centres half a spacing in from its faces.
        xs = np.arange(gap_mm - 10.0 + 5.0, 186.0 - 5.0 + 1e-6, 10.0) / 1000.0
        ys = np.arange(16.0 + 10.0 + 5.0, 16.0 + 110.0 - 5.0 + 1e-6, 10.0) / 1000.0
        points = np.array([[x, y, 0.0] for y in ys for x in xs])
    gap_m, energy = start_contact(points, wall, dimension, stiffness, wall_spacing)
    weight = len(points) * mass_particle * GRAVITY * SPACING
    if results[True] is None:
        status, peak_g = "refused", math.nan
    else:
        summary, peak_g, _, _ = results[True]
        status = summary["status"]
        if status != "completed":
            status = f"{status} at {summary['simulated_time_s']:.3f} s"
    row.update({
        "gap_mm": 1000.0 * gap_m, "gap_2h": gap_m / REACH, "gap_spacings": gap_m / SPACING,
        "E0_J": energy, "E0_over_Mgs": energy / weight,
        "status": status,
        "KE_push_over_Mgs": 0.5 * mass_particle * peak_push / weight,
        "KE_g_over_Mgs": 0.5 * mass_particle * peak_g / weight,
    })
    return row


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("grainload")
    parser.add_argument("out_dir")
    parser.add_argument("--series", default="floor,side,stiff,tall,fine,source,floor3d")
    parser.add_argument("--gaps", default=",".join(str(g) for g in GAPS))
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--end", type=float, default=0.1)
    args = parser.parse_args()
    gaps = [float(g) for g in args.gaps.split(",")]
    tasks = [(s, g) for s in args.series.split(",") for g in gaps]
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        rows = list(pool.map(lambda t: one(os.path.abspath(args.grainload), args.out_dir, t[0],
                                           t[1], args.end), tasks))
    os.makedirs(args.out_dir, exist_ok=True)
    with open(os.path.join(args.out_dir, "start_gap_sweep.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        writer.writeheader()
        writer.writerows(rows)
    print_tables(rows)


def survived(row):
    return row["status"] == "completed"


def print_tables(rows):
    """Per series, where runs stop dying and what the push gives; then every run."""
    print("| series | died at E0/Mgs >= | survived up to E0/Mgs | peak KE push / E0 "
          "(E0 > 0) | KE / Mgs at 2h (gravity) |")
    print("| --- | --- | --- | --- | --- |")
    for series in dict.fromkeys(r["series"] for r in rows):
        group = [r for r in rows if r["series"] == series]
        died = [r["E0_over_Mgs"] for r in group if r["status"].startswith("unstable")]
        lived = [r["E0_over_Mgs"] for r in group if survived(r)]
        push = [r["KE_push_over_Mgs"] / r["E0_over_Mgs"] for r in group if r["E0_over_Mgs"] > 0]
        settle = [r["KE_g_over_Mgs"] for r in group if r["E0_over_Mgs"] == 0]
        print(f"| {series} | {min(died):.3g} | {max(lived):.3g} | "
              f"{min(push):.2f}-{max(push):.2f} | {settle[0]:.2g} |" if died else
              f"| {series} | - | {max(lived):.3g} | {min(push):.2f}-{max(push):.2f} | "
              f"{settle[0]:.2g} |")
    print()
    print("| series | g [mm] | g / 2h | g / s | E0 [J] | E0 / Mgs | status (gravity) | "
          "KE push / Mgs | KE / Mgs with gravity |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    for r in rows:
        print(f"| {r['series']} | {r['gap_mm']:.1f} | {r['gap_2h']:.3f} | {r['gap_spacings']:.2f} "
              f"| {r['E0_J']:.3g} | {r['E0_over_Mgs']:.3g} | {r['status']} | "
              f"{r['KE_push_over_Mgs']:.3g} | {r['KE_g_over_Mgs']:.3g} |")


if __name__ == "__main__":
    main()
