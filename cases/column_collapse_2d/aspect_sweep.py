#!/usr/bin/python3
"""Aspect-ratio sweep of the plane-strain column collapse against the published scaling laws.

Usage:
    /usr/bin/python3 cases/column_collapse_2d/aspect_sweep.py GRAINLOAD OUT_DIR
        [--aspects 0.5,1,2,3,4,6] [--spacing-mm 4] [--length-mm 80] [--threads 1]
        [--case CASE.toml] [--label TEXT] [--beside OTHER_OUT_DIR --beside-label TEXT]
        [--analyse-only]

Runs cases/column_collapse_2d/column_collapse_2d.toml (or --case: column_collapse_2d_mu_i.toml,
the same scene with the mu(I) material) once per aspect ratio a = H0/L0 with the
column length L0 fixed and H0 = a L0 (same material, friction floor and walls; only the box, the
spacing, the back wall's height and the end time are overridden with --set), then measures the
final run-out, height and rest state with analyse.py's definitions and writes
OUT_DIR/aspect_sweep.csv and OUT_DIR/aspect_sweep.svg (normalised run-out (L_inf - L0)/L0 and
final height H_inf/L0 against a, beside the laws below; with --beside, also the points of
another sweep's aspect_sweep.csv, e.g. the Drucker-Prager sweep beside the mu(I) one).

Scaling laws (final deposit of a column released on a horizontal plane; L0 initial length):
  * Lube et al. (2005), quasi-2D channel:  (L_inf - L0)/L0 = 1.2 a for a < 1.8,
    1.9 a^(2/3) for a > 2.8; H_inf/L0 = a for a < 1.15, a^(2/5) beyond.
  * Lajeunesse et al. (2005), quasi-2D channel: (L_inf - L0)/L0 = a for a < 3, 1.9 a^(2/3)
    beyond (both groups' constants as quoted in the secondary literature).
  * Nguyen et al. (2015, arXiv:1512.05180), true 2D aluminium rods (the material of this case):
    H_inf = H0 for a < 0.65; (L_inf - L0)/L0 = 3.25 a^0.96 for 0.65 < a < 1.5, 3.80 a^0.73 for
    a > 1.5; H0/H_inf = 1.42 a^(2/3) for a > 0.65.
"""

import argparse
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import analyse  # noqa: E402

CASE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "column_collapse_2d.toml")
GRAVITY = 9.81


def end_time(height):
    """Long enough for the heap to stop: the collapse lasts a few free-fall times sqrt(H0/g)."""
    return max(0.6, 6.0 * math.sqrt(height / GRAVITY))


def floor_length(aspect, length):
    """Floor long enough for the run-out: twice Lube et al.'s law, whose rate the SPH exceeds."""
    return max(1.0, 2.0 * (1.0 + 1.9 * aspect ** (2.0 / 3.0)) * length / 1000.0 + 0.1)


def overrides(aspect, dp_mm, length_mm):
    height_mm = aspect * length_mm
    return analyse.placement_overrides(dp_mm, length_mm, height_mm) + [
        f"case.end_time={end_time(height_mm / 1000.0):.3f} s",
        f"sph.wall[1].edge_u=0 {1.6 * height_mm:g} mm",
        f"sph.wall[0].edge_u={1000.0 * floor_length(aspect, length_mm):.0f} 0 mm",
    ]


def measure(out):
    d = analyse.deposit(analyse.frame_files(out)[-1])
    _, energies = analyse.kinetic_history(out, "column")
    return {
        "a": d["H0"] / d["L0"], "L0": d["L0"], "H0": d["H0"], "L_inf": d["L_inf"],
        "H_inf": d["H_inf"], "runout": (d["L_inf"] - d["L0"]) / d["L0"],
        "height": d["H_inf"] / d["L0"], "rest": energies[-1] / max(energies),
        "outside": int((~d["bulk"]).sum()), "particles": len(d["pos"]),
    }


def lube_runout(a):
    return 1.2 * a if a < 1.8 else (1.9 * a ** (2 / 3) if a > 2.8 else float("nan"))


def lajeunesse_runout(a):
    return a if a < 3.0 else 1.9 * a ** (2 / 3)


def nguyen_runout(a):
    if a < 0.65:
        return float("nan")
    return 3.25 * a ** 0.96 if a < 1.5 else 3.80 * a ** 0.73


def read_rows(csv):
    """(a, normalised run-out) of a sweep's aspect_sweep.csv."""
    data = np.genfromtxt(csv, delimiter=",", names=True)
    return [{"a": float(a), "runout": float(r)}
            for a, r in zip(np.atleast_1d(data["a"]), np.atleast_1d(data["runout_normalised"]))]


def write_svg(path, rows, label, beside=None, beside_label=""):
    """Normalised run-out against the aspect ratio: the runs as dots (another sweep's, `beside`,
    as open circles), the laws as lines, each named in the legend (matplotlib)."""
    import matplotlib
    matplotlib.use("Agg")
    matplotlib.rcParams["svg.hashsalt"] = "grainload"  # the same runs draw the same file
    import matplotlib.pyplot as plt
    amax = max(6.0, max(r["a"] for r in rows))
    grid = np.linspace(0.05, amax, 400)
    figure, axes = plt.subplots(figsize=(7, 4.6), layout="constrained")
    for law, colour, style, name in ((lube_runout, "C0", "-", "Lube et al. 2005 (quasi-2D)"),
                                      (lajeunesse_runout, "C2", "--",
                                       "Lajeunesse et al. 2005 (quasi-2D)"),
                                      (nguyen_runout, "C4", "-.",
                                       "Nguyen et al. 2015 (2D aluminium rods)")):
        axes.plot(grid, [law(a) for a in grid], color=colour, linestyle=style, label=name)
    if beside:
        axes.plot([r["a"] for r in beside], [r["runout"] for r in beside], "o", color="C7",
                  markerfacecolor="none", label=beside_label)
    axes.plot([r["a"] for r in rows], [r["runout"] for r in rows], "o", color="C3", label=label)
    axes.set_xlim(0, amax)
    axes.set_ylim(0, None)
    axes.set_xlabel("aspect ratio a = H0 / L0")
    axes.set_ylabel("normalised run-out (L∞ − L0) / L0")
    axes.grid(True, alpha=0.3)
    axes.legend(loc="upper left", fontsize="small")
    figure.savefig(path, metadata={"Date": None})
    plt.close(figure)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("grainload")
    ap.add_argument("out_dir")
    ap.add_argument("--aspects", default="0.5,1,2,3,4,6")
    ap.add_argument("--spacing-mm", type=float, default=4.0)
    ap.add_argument("--length-mm", type=float, default=80.0)
    ap.add_argument("--threads", type=int, default=1)
    ap.add_argument("--case", default=CASE,
                    help="the plane-strain collapse to sweep (its walls and body as in the default)")
    ap.add_argument("--label", default="grainload SPH", help="the legend of this sweep's points")
    ap.add_argument("--beside", help="another sweep's OUT_DIR whose points the plot also shows")
    ap.add_argument("--beside-label", default="grainload SPH, other sweep")
    ap.add_argument("--analyse-only", action="store_true", help="measure existing runs only")
    args = ap.parse_args()
    os.makedirs(args.out_dir, exist_ok=True)
    rows = []
    for aspect in (float(a) for a in args.aspects.split(",")):
        out = os.path.join(args.out_dir, f"a{aspect:g}")
        if not args.analyse_only:
            analyse.run_case(args.grainload, args.case, out, args.threads,
                             overrides(aspect, args.spacing_mm, args.length_mm))
        rows.append(measure(out))
        r = rows[-1]
        print(f"a = {r['a']:.3g}: (L_inf - L0)/L0 = {r['runout']:.3f} (Lube {lube_runout(r['a']):.3g}, "
              f"Lajeunesse {lajeunesse_runout(r['a']):.3g}, Nguyen {nguyen_runout(r['a']):.3g}), "
              f"H_inf/L0 = {r['height']:.3f}, H_inf/H0 = {r['H_inf'] / r['H0']:.3f}, "
              f"KE end/peak = {r['rest']:.1e}, {r['outside']} of {r['particles']} outside the heap",
              flush=True)
    csv = os.path.join(args.out_dir, "aspect_sweep.csv")
    with open(csv, "w") as f:
        f.write("a,L0_m,H0_m,L_inf_m,H_inf_m,runout_normalised,height_over_L0,"
                "lube_runout,lajeunesse_runout,nguyen_runout,ke_end_over_peak,outside\n")
        for r in rows:
            f.write(f"{r['a']:.4f},{r['L0']:.4f},{r['H0']:.4f},{r['L_inf']:.4f},{r['H_inf']:.4f},"
                    f"{r['runout']:.4f},{r['height']:.4f},{lube_runout(r['a']):.4f},"
                    f"{lajeunesse_runout(r['a']):.4f},{nguyen_runout(r['a']):.4f},"
                    f"{r['rest']:.3e},{r['outside']}\n")
    beside = read_rows(os.path.join(args.beside, "aspect_sweep.csv")) if args.beside else None
    write_svg(os.path.join(args.out_dir, "aspect_sweep.svg"), rows, args.label, beside,
              args.beside_label)
    print(f"written: {csv}, {os.path.join(args.out_dir, 'aspect_sweep.svg')}")


if __name__ == "__main__":
    main()
