#!/usr/bin/env python3
"""Error against wall time of a `grainload trade` sweep, one panel per figure.

Usage: plot_trade.py DIR/trade.csv OUT.svg [--budget 0.02] [--figures NAME,...]

Each completed run is a point: x its elapsed time, y |change| of the figure against the most
accurate run of the grid (relative; the most accurate run itself, at 0, sits on the floor of the
log axis). The budget is a dashed line, the knee a ring, runs outside the budget grey. With a
round-off ensemble (`--noise`), changes are against the ensemble's mean, its members are crosses
and a dotted line marks the figure's tolerance where its 2-sigma scatter exceeds the budget. Runs
that failed or went unstable are not drawn (they are rows of trade.csv). Called by `grainload trade`
at the end of a sweep; exits with 4 and says so when matplotlib is missing (Debian:
python3-matplotlib, installed by scripts/ensure_packages.sh).
"""

import argparse
import csv
import math
import sys

try:
    import matplotlib

    matplotlib.use("Agg")
    matplotlib.rcParams["svg.fonttype"] = "none"  # text as text: small, diffable SVG
    import matplotlib.pyplot as plt
except ImportError:
    print("matplotlib is not installed (Debian package python3-matplotlib)", file=sys.stderr)
    sys.exit(4)

# Changes below budget / FLOOR_DECADES are drawn on the floor of the log axis (the most accurate
# run is 0), so the axis spans what matters around the budget.
FLOOR_DECADES = 100.0


def read_rows(path):
    with open(path, newline="") as f:
        reader = csv.DictReader(f)
        rows = list(reader)
        fields = reader.fieldnames
    # The axis columns stand between "run" and "status": a run is labelled by its values.
    axes = fields[1:fields.index("status")]
    for r in rows:
        r["label"] = ", ".join(r[a] for a in axes)
        if r.get("noise_member") not in (None, "", "0"):
            r["label"] = "noise " + r["noise_member"]
    return rows, axes


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("csv")
    parser.add_argument("out")
    parser.add_argument("--budget", type=float, default=0.02)
    parser.add_argument("--figures", default="")
    args = parser.parse_args()
    rows, axes_keys = read_rows(args.csv)
    rows = [r for r in rows if r["figure"]]
    floor = args.budget / FLOOR_DECADES
    chosen = [f for f in args.figures.split(",") if f]
    figures = chosen or sorted({r["figure"] for r in rows if r["change"]})
    if not figures:
        print("no figure has a change against the most accurate run", file=sys.stderr)
        return 3
    columns = min(3, len(figures))
    lines = math.ceil(len(figures) / columns)
    fig, axes = plt.subplots(lines, columns, figsize=(4.2 * columns, 3.4 * lines), squeeze=False)
    for index, (panel, name) in enumerate(zip(axes.flat, figures)):
        points = [r for r in rows if r["figure"] == name and r["status"] == "completed"
                  and r["change"] not in ("", "inf", "-inf")]
        for r in points:
            change = max(abs(float(r["change"])), floor)
            inside = r["within_budget"] == "1"
            member = r.get("noise_member") not in (None, "", "0")
            panel.scatter(float(r["elapsed_s"]), change, color="C0" if inside else "0.6",
                          marker="x" if member else "o", zorder=3)
            if r["knee"] == "1":
                panel.scatter(float(r["elapsed_s"]), change, s=160, facecolors="none",
                              edgecolors="C3", linewidths=1.5, zorder=4, label="knee")
            panel.annotate(r["label"], (float(r["elapsed_s"]), change), fontsize=6,
                           xytext=(3, 3), textcoords="offset points",
                           color="black" if inside else "0.45")
        panel.axhline(args.budget, color="C3", linestyle="--", linewidth=1, label="budget")
        tolerances = {float(r["tolerance"]) for r in points if r.get("tolerance")}
        if tolerances and max(tolerances) > args.budget:
            panel.axhline(max(tolerances), color="C1", linestyle=":", linewidth=1.2,
                          label="2 sigma of round-off")
        panel.set_xscale("log")
        panel.set_yscale("log")
        panel.set_title(name, fontsize=9)
        panel.set_xlabel("elapsed time (s)")
        panel.set_ylabel("|change| against the most accurate run")
        if index == 0:
            panel.legend(fontsize=7, loc="lower left")
    for panel in list(axes.flat)[len(figures):]:
        panel.axis("off")
    fig.suptitle("runs labelled " + ", ".join(axes_keys) + f"; floor = change < {floor:g}",
                 fontsize=8)
    fig.tight_layout()
    fig.savefig(args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
