#!/usr/bin/python3
"""Analyse a plane-strain granular column collapse run (cases/column_collapse_2d).

Usage:
    /usr/bin/python3 cases/column_collapse_2d/analyse.py OUT_DIR [--body column]
        [--frame N] [--csv FILE] [--svg FILE] [--history]

Reads the last frame (or frame N) of OUT_DIR/frames/*.vtm, takes the SPH body named --body,
and prints:
  * the final surface profile: free-surface height vs x in bins of 2 particle spacings
    (also written as CSV, default OUT_DIR/profile.csv);
  * the run-out L_inf, the final height H_inf, the normalised run-out (L_inf - L0)/L0 and
    H_inf/H0;
  * the failure-line angle and the heap's flank angle (heap_angle);
  * with --history: kinetic energy, largest speed and run-out of every frame (is the heap at rest?).

Coordinates. x and y are measured from the column's initial back face and base, i.e. from
min(initial x) - dp/2 and min(initial y) - dp/2, where "initial" = position - displacement.
The case files leave a contact gap between the walls' planes and the material (the contact
potential's range), so the wall planes are not the natural origin.

Run-out criterion. Two particles are "in contact" when their centres are closer than
LINK * dp (LINK = 1.5: nearest neighbours in a lattice sit 1 dp apart, diagonal ones 1.41 dp; a
particle that has left the bulk is further than 1.5 dp from every other one). The bulk is the
largest connected set under this relation (a chain of touching particles along the floor is
part of the bulk). L_inf is the largest x + dp/2 over the bulk; particles outside the bulk are
counted and their furthest x reported separately, but not used.

Failure line. A particle "moved" when its final displacement exceeds MOVED_FRACTION (10 %) of H0. In the
initial configuration, for every lattice row (constant initial y) that holds both moved and
unmoved particles, the boundary point is the initial x of the furthest unmoved particle that is
connected to the back wall through unmoved particles of that row, plus dp/2. A least-squares
line y = m x + b through those boundary points gives the failure angle atan(|m|) from the
horizontal. Rows without unmoved particles (above the static wedge) are skipped. (Until
2026-11-22 the threshold was one spacing, which marked the whole column as moved once the floor
had friction: the column settles ~dp/2 onto the contact layer and sinks while it spreads.)
"""

import argparse
import glob
import math
import os
import subprocess
import sys
import xml.etree.ElementTree as ET

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy

LINK = 1.5  # contact distance in spacings for the bulk/isolated-particle criterion
THICK_FRACTION = 0.05  # deposit thickness, as a fraction of H0, that defines the front L_5%
# A particle "moved" (failure line) when its displacement exceeds this fraction of H0. A fixed
# physical threshold: the whole column first settles about dp/2 onto the walls' contact layer
# and sinks a few per cent while it spreads, so a threshold of one spacing marks all of it.
MOVED_FRACTION = 0.1


def frame_files(out_dir):
    files = sorted(glob.glob(os.path.join(out_dir, "frames", "*.vtm")))
    if not files:
        sys.exit(f"analyse.py: no frames/*.vtm in {out_dir}")
    return files


def frame_times(out_dir):
    """Map frame file basename -> time from the .pvd collection (if any)."""
    times = {}
    for pvd in glob.glob(os.path.join(out_dir, "*.pvd")):
        for ds in ET.parse(pvd).getroot().iter("DataSet"):
            times[os.path.basename(ds.get("file"))] = float(ds.get("timestep"))
    return times


def read_body(vtm_file, body):
    base = os.path.splitext(vtm_file)[0]
    path = os.path.join(base, body + ".vtp")
    if not os.path.exists(path):
        found = [os.path.basename(p) for p in glob.glob(os.path.join(base, "*.vtp"))]
        sys.exit(f"analyse.py: no {body}.vtp in {base} (found: {', '.join(found)})")
    reader = vtk.vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    data = reader.GetOutput()
    pos = vtk_to_numpy(data.GetPoints().GetData()).astype(float)
    pd = data.GetPointData()
    fields = {pd.GetArrayName(i): vtk_to_numpy(pd.GetArray(i)) for i in range(pd.GetNumberOfArrays())}
    return pos, fields


def spacing_of(initial):
    """Lattice spacing from the initial positions (smallest gap between distinct x values)."""
    xs = np.unique(np.round(initial[:, 0], 9))
    gaps = np.diff(xs)
    gaps = gaps[gaps > 1e-9]
    return float(np.median(gaps))


def components(points, link):
    """Connected components of the graph 'distance < link' (cell list + union-find)."""
    n = len(points)
    parent = np.arange(n)

    def find(i):
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    cells = {}
    keys = np.floor(points[:, :2] / link).astype(np.int64)
    for i, (a, b) in enumerate(keys):
        cells.setdefault((a, b), []).append(i)
    link2 = link * link
    for (a, b), members in cells.items():
        cand = []
        for da in (-1, 0, 1):
            for db in (-1, 0, 1):
                cand.extend(cells.get((a + da, b + db), ()))
        cand = np.array(cand)
        for i in members:
            d2 = np.sum((points[cand, :2] - points[i, :2]) ** 2, axis=1)
            for j in cand[(d2 < link2) & (cand > i)]:
                ri, rj = find(i), find(j)
                if ri != rj:
                    parent[max(ri, rj)] = min(ri, rj)
    return np.array([find(i) for i in range(n)])


def bulk_mask(pos, dp):
    labels = components(pos, LINK * dp)
    values, counts = np.unique(labels, return_counts=True)
    return labels == values[np.argmax(counts)]


def failure_line(initial, moved, dp, x0, y0):
    rows = np.round((initial[:, 1] - y0) / dp - 0.5).astype(int)
    cols = np.round((initial[:, 0] - x0) / dp - 0.5).astype(int)
    pts = []
    for r in np.unique(rows):
        in_row = rows == r
        c_moved = set(cols[in_row & moved])
        c_still = set(cols[in_row & ~moved])
        if not c_still or not c_moved or 0 not in c_still:
            continue
        c = 0
        while c + 1 in c_still:
            c += 1
        pts.append(((c + 1) * dp, (r + 0.5) * dp))
    if len(pts) < 3:
        return None, pts
    p = np.array(pts)
    m, b = np.polyfit(p[:, 0], p[:, 1], 1)
    return (math.degrees(math.atan(abs(m))), m, b), pts


def profile(pos_b, dp, x0, y0, width):
    xr = pos_b[:, 0] - x0
    top = pos_b[:, 1] - y0 + 0.5 * dp
    nbins = int(xr.max() // width) + 1
    rows = []
    for k in range(nbins):
        sel = (xr >= k * width) & (xr < (k + 1) * width)
        h = float(top[sel].max()) if np.any(sel) else 0.0
        rows.append(((k + 0.5) * width, h, int(np.sum(sel))))
    return rows


def front_at(prof, thickness):
    """Run-out measured where the deposit is still `thickness` deep: the largest x at which the
    profile height reaches it (linear between bins). The bulk's last particle (L_inf) sits in a
    tail one or two particles thick, so L_inf moves with the spacing; a fixed physical thickness
    (THICK_FRACTION of H0) does not."""
    for k in range(len(prof) - 1, -1, -1):
        if prof[k][1] >= thickness:
            if k + 1 < len(prof):
                (x0, h0, _), (x1, h1, _) = prof[k], prof[k + 1]
                return x0 + (h0 - thickness) / (h0 - h1) * (x1 - x0)
            return prof[k][0]
    return 0.0


def deposit(vtm, body="column"):
    """One frame's deposit, measured as in the module docstring: a dict with the particles
    (pos, fields, initial, bulk mask), the initial column (L0, H0, dp, origin x0, y0), the bulk's
    run-out L_inf and height H_inf, the profile and the failure-line fit (None if not found)
    with its boundary points."""
    pos, fields = read_body(vtm, body)
    disp = fields["displacement"].astype(float)
    initial = pos - disp
    dp = spacing_of(initial)
    x0 = initial[:, 0].min() - 0.5 * dp
    y0 = initial[:, 1].min() - 0.5 * dp
    H0 = initial[:, 1].max() + 0.5 * dp - y0
    bulk = bulk_mask(pos, dp)
    moved = np.linalg.norm(disp[:, :2], axis=1) > MOVED_FRACTION * H0
    fit, points = failure_line(initial, moved, dp, x0, y0)
    return {
        "pos": pos, "fields": fields, "initial": initial, "bulk": bulk, "moved": moved,
        "dp": dp, "x0": x0, "y0": y0, "L0": initial[:, 0].max() + 0.5 * dp - x0, "H0": H0,
        "L_inf": pos[bulk, 0].max() + 0.5 * dp - x0, "H_inf": pos[bulk, 1].max() + 0.5 * dp - y0,
        "profile": profile(pos[bulk], dp, x0, y0, 2 * dp), "failure": fit,
        "failure_points": points,
    }


def heap_angle(prof, height):
    """Flank angle of the final heap: least-squares slope of the profile heights that lie
    between 20 % and 80 % of the final height, taken from the highest bin onwards (the downhill
    flank). Returns degrees from the horizontal, or None with fewer than 3 bins."""
    xs = np.array([r[0] for r in prof])
    hs = np.array([r[1] for r in prof])
    start = int(np.argmax(hs))
    sel = np.arange(len(hs)) >= start
    sel &= (hs >= 0.2 * height) & (hs <= 0.8 * height)
    if np.count_nonzero(sel) < 3:
        return None
    slope = np.polyfit(xs[sel], hs[sel], 1)[0]
    return math.degrees(math.atan(abs(slope)))


def placement_overrides(dp_mm, length_mm, height_mm):
    """`--set` items that give column_collapse_2d.toml another spacing and column size: the box
    starts 1.85 dp from both wall planes (first particle centres 2h from the first wall layer,
    dp/4 behind the plane; see the case file) and the walls are sampled at dp/2."""
    offset = 1.85 * dp_mm
    return [
        f"sph.body[0].spacing={dp_mm:g} mm",
        f"sph.body[0].shape.min={offset:g} {offset:g} mm",
        f"sph.body[0].shape.max={offset + length_mm:g} {offset + height_mm:g} mm",
        f"sph.wall[0].spacing={dp_mm / 2:g} mm",
        f"sph.wall[1].spacing={dp_mm / 2:g} mm",
    ]


def run_case(grainload, case, out, threads, overrides):
    """`grainload run case --out out` with `--set` overrides, its output in out + ".log"."""
    cmd = [grainload, "run", case, "--out", out, "--threads", str(threads)]
    for item in overrides:
        cmd += ["--set", item]
    with open(out + ".log", "w") as log:
        subprocess.run(cmd, check=True, stdout=log, stderr=subprocess.STDOUT,
                       env=dict(os.environ, OMP_WAIT_POLICY="PASSIVE"))


def kinetic_history(out_dir, body):
    """(frame times, sum of |v|^2 per frame): the body's kinetic energy up to the particle mass."""
    files = frame_files(out_dir)
    times = frame_times(out_dir)
    energies = []
    for vtm in files:
        _, f = read_body(vtm, body)
        energies.append(float(np.sum(f["velocity"].astype(float)[:, :2] ** 2)))
    return [times.get(os.path.basename(vtm), float("nan")) for vtm in files], energies


def rest_time(out_dir, body, fraction=1e-4):
    """First output time after the kinetic-energy peak at which the body's kinetic energy is
    below `fraction` of that peak (the "time to rest" of the collapse cases); None if never."""
    times, energies = kinetic_history(out_dir, body)
    peak = int(np.argmax(energies))
    for k in range(peak, len(energies)):
        if energies[k] < fraction * energies[peak]:
            return times[k]
    return None


def write_svg(path, prof, L0, H0, fit, dp):
    """The final profile drawn to scale (matplotlib, lengths in m): the deposit, the initial
    column dashed, the failure line and the run-out."""
    import matplotlib
    matplotlib.use("Agg")
    matplotlib.rcParams["svg.hashsalt"] = "grainload"  # the same runs draw the same file
    import matplotlib.pyplot as plt
    x = [0.0] + [r[0] for r in prof] + [prof[-1][0]]
    h = [0.0] + [r[1] for r in prof] + [0.0]
    figure, axes = plt.subplots(figsize=(9, 3.6), layout="constrained")
    axes.fill(x, h, color="#e8c07a", edgecolor="black", linewidth=0.8, label="final deposit")
    axes.plot([0, L0, L0, 0], [0, 0, H0, H0], color="0.4", linestyle="--", linewidth=1,
              label="initial column")
    if fit:
        angle, m, b = fit
        x_base = -b / m if m != 0 else L0
        axes.plot([0, x_base], [b, 0], color="C3", linewidth=1.2,
                  label=f"failure line, {angle:.1f}° from the floor")
    axes.set_aspect("equal")
    axes.set_xlim(0, max(x) * 1.03)
    axes.set_ylim(0, max(H0, max(h)) * 1.15)
    axes.set_xlabel("distance from the back wall x (m)")
    axes.set_ylabel("height y (m)")
    axes.set_title(f"final surface profile, spacing {dp * 1e3:g} mm (bins of 2 spacings)")
    axes.grid(True, alpha=0.3)
    axes.legend(loc="upper right", fontsize="small")
    figure.savefig(path, metadata={"Date": None})
    plt.close(figure)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[1])
    ap.add_argument("out_dir")
    ap.add_argument("--body", default="column")
    ap.add_argument("--frame", type=int, help="frame index (default: last)")
    ap.add_argument("--csv", help="profile CSV (default OUT_DIR/profile.csv)")
    ap.add_argument("--svg", help="write an SVG sketch of the final profile")
    ap.add_argument("--history", action="store_true", help="kinetic energy per frame")
    ap.add_argument("--failure-history", action="store_true",
                    help="failure line per frame, for moved thresholds of 1, 2, 5 and 10 %% of H0")
    args = ap.parse_args()

    files = frame_files(args.out_dir)
    times = frame_times(args.out_dir)
    vtm = files[-1] if args.frame is None else files[args.frame]
    d = deposit(vtm, args.body)
    pos, f, bulk, moved = d["pos"], d["fields"], d["bulk"], d["moved"]
    dp, x0, y0, L0, H0 = d["dp"], d["x0"], d["y0"], d["L0"], d["H0"]
    L_inf, H_inf, prof = d["L_inf"], d["H_inf"], d["profile"]
    fit, fpts = d["failure"], d["failure_points"]
    vel = f["velocity"].astype(float)
    t = times.get(os.path.basename(vtm), float("nan"))
    L_all = pos[:, 0].max() + 0.5 * dp - x0
    rho = f["density"].astype(float) if "density" in f else None
    speed = np.linalg.norm(vel[:, :2], axis=1)

    print(f"frame {os.path.basename(vtm)}  t = {t:.4g} s  particles {len(pos)}  dp = {dp * 1e3:.3g} mm")
    print(f"initial column L0 = {L0:.4f} m, H0 = {H0:.4f} m, a = H0/L0 = {H0 / L0:.3f}")
    print(f"\nfinal surface profile (bins of 2 dp = {2 * dp * 1e3:.3g} mm; height of the highest bulk "
          "particle top in the bin)")
    print("   x_centre_m  height_m  particles")
    for x, h, n in prof:
        print(f"   {x:10.4f}  {h:8.4f}  {n:9d}")
    print(f"\nbulk: {int(bulk.sum())} particles; {int((~bulk).sum())} outside it "
          f"(link {LINK} dp); furthest particle of all at x = {L_all:.4f} m")
    print(f"run-out L_inf            = {L_inf:.4f} m")
    print(f"final height H_inf       = {H_inf:.4f} m   (H_inf/H0 = {H_inf / H0:.3f})")
    print(f"height at the back wall  = {prof[0][1]:.4f} m")
    print(f"normalised run-out (L_inf - L0)/L0 = {(L_inf - L0) / L0:.3f}")
    L_thick = front_at(prof, THICK_FRACTION * H0)
    print(f"front where the deposit is {THICK_FRACTION * H0 * 1e3:.3g} mm deep (5 % of H0): "
          f"L_5% = {L_thick:.4f} m, (L_5% - L0)/L0 = {(L_thick - L0) / L0:.3f}")
    angle = heap_angle(prof, H_inf)
    print("heap angle (flank, 20-80 % of the height) = " +
          (f"{angle:.1f} deg" if angle is not None else "not found"))
    if fit:
        ang, m, b = fit
        print(f"failure line: {ang:.1f} deg from horizontal (fit through {len(fpts)} row boundaries; "
              f"meets the back wall at y = {b:.4f} m, the base at x = {-b / m:.4f} m)")
    else:
        print(f"failure line: not found (only {len(fpts)} rows with a static part next to the wall)")
    print(f"moved > {MOVED_FRACTION * H0 * 1e3:.3g} mm (10 % of H0): {int(moved.sum())} of "
          f"{len(pos)} particles")
    print(f"last frame: max speed {speed.max():.3g} m/s, mean speed {speed.mean():.3g} m/s")
    if rho is not None:
        print(f"density: min {rho.min():.1f}, max {rho.max():.1f} kg/m^3")

    csv = args.csv or os.path.join(args.out_dir, "profile.csv")
    with open(csv, "w") as out:
        out.write("x_centre_m,height_m,particles\n")
        for x, h, n in prof:
            out.write(f"{x:.5f},{h:.5f},{n}\n")
    print(f"profile written to {csv}")
    if args.svg:
        write_svg(args.svg, prof, L0, H0, fit, dp)
        print(f"sketch written to {args.svg}")

    if args.history:
        # particle mass per unit thickness = rho0 dp^2, rho0 = mean density of the first frame
        p0, f0 = read_body(files[0], args.body)
        rho0 = float(np.mean(f0["density"])) if "density" in f0 else float("nan")
        print(f"\n   t_s      kinetic_J/m   max_speed_m/s  runout_m   (particle mass rho0 dp^2, rho0 = {rho0:.1f})")
        for vf in files:
            p, ff = read_body(vf, args.body)
            v = ff["velocity"].astype(float)
            sp2 = np.sum(v[:, :2] ** 2, axis=1)
            ke = 0.5 * rho0 * dp * dp * sp2.sum()
            b = bulk_mask(p, dp)
            print(f"   {times.get(os.path.basename(vf), float('nan')):6.3f}  {ke:12.5g}  "
                  f"{np.sqrt(sp2).max():12.4g}  {p[b, 0].max() + 0.5 * dp - x0:8.4f}")
    if args.failure_history:
        print_failure_history(files, times, args.body)


def print_failure_history(files, times, body):
    """The failure line of every frame (same fit as the final one) for several thresholds of
    displacement: early frames show the first failure surface, before the collapse retrogresses
    into the column and the line flattens."""
    fractions = (0.01, 0.02, 0.05, MOVED_FRACTION)
    print("\n   t_s    failure line (deg) for moved > " +
          " / ".join(f"{100 * f:g} %" for f in fractions) + " of H0")
    for vf in files[1:]:
        d = deposit(vf, body)
        moved_by = np.linalg.norm(d["fields"]["displacement"].astype(float)[:, :2], axis=1)
        angles = []
        for fraction in fractions:
            fit, _ = failure_line(d["initial"], moved_by > fraction * d["H0"], d["dp"], d["x0"],
                                  d["y0"])
            angles.append(f"{fit[0]:6.1f}" if fit else "   nan")
        print(f"   {times.get(os.path.basename(vf), float('nan')):6.3f}  " + "  ".join(angles))


if __name__ == "__main__":
    main()
