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
    # The same table draws the same file: fixed element ids, and no date (savefig below).
    matplotlib.rcParams["svg.hashsalt"] = "grainload"
    import matplotlib.pyplot as plt
    from matplotlib.ticker import LogFormatter
    from matplotlib.transforms import Bbox
except ImportError:
    print("matplotlib is not installed (Debian package python3-matplotlib)", file=sys.stderr)
    sys.exit(4)

# Changes below budget / FLOOR_DECADES are drawn on the floor of the log axis (the most accurate
# run is 0), so the axis spans what matters around the budget.
FLOOR_DECADES = 100.0
# Run labels: readable where the plot is shown at the page's width (about 900 pixels).
LABEL_SIZE = 7.5


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


def groups_of(points, panel):
    """The panel's points that fall on the same spot (centres within 12 pixels: their markers,
    8 pixels across, touch or nearly) grouped: (x, y, label, inside budget) each, the labels
    of a group joined with "; "."""
    groups = []
    for x, y, label, inside in points:
        px, py = panel.transData.transform((x, y))
        for g in groups:
            if abs(g["px"] - px) <= 12 and abs(g["py"] - py) <= 12:
                g["labels"].append(label)
                g["inside"] = g["inside"] or inside
                break
        else:
            groups.append({"x": x, "y": y, "px": px, "py": py, "labels": [label],
                           "inside": inside})
    return groups


def overlap(a, b):
    width = min(a.x1, b.x1) - max(a.x0, b.x0)
    height = min(a.y1, b.y1) - max(a.y0, b.y0)
    return width * height if width > 0 and height > 0 else 0.0


def place_labels(figure, panel, groups, taken):
    """Labels beside their points where they overlap no other label, marker, legend or the
    panel's edge: the first free place of a ring of candidates around the point, then of wider
    rings, with a thin leader line from the third ring on; where none is free, the place of
    least overlap. `taken` holds the pixel boxes already used in the panel."""
    renderer = figure.canvas.get_renderer()
    frame = panel.get_window_extent(renderer)
    ring = [(6, 4, "left", "bottom"), (6, -4, "left", "top"), (-6, 4, "right", "bottom"),
            (-6, -4, "right", "top"), (0, 8, "center", "bottom"), (0, -8, "center", "top"),
            (9, 0, "left", "center"), (-9, 0, "right", "center")]
    for g in sorted(groups, key=lambda g: (g["px"], g["py"])):
        best = None
        for reach in (1.0, 2.2, 3.6, 5.0):
            for dx, dy, ha, va in ring:
                note = panel.annotate(
                    "; ".join(g["labels"]), (g["x"], g["y"]), xytext=(dx * reach, dy * reach),
                    textcoords="offset points", ha=ha, va=va, fontsize=LABEL_SIZE,
                    color="black" if g["inside"] else "0.4",
                    bbox=dict(boxstyle="square,pad=0.1", facecolor="white", edgecolor="none",
                              alpha=0.8),
                    arrowprops=dict(arrowstyle="-", color="0.6", linewidth=0.6, shrinkA=0,
                                    shrinkB=4) if reach > 2.5 else None)
                box = note.get_window_extent(renderer)
                outside = box.width * box.height - overlap(box, frame)
                cost = outside + sum(overlap(box, t) for t in taken)
                if best is None or cost < best[0]:
                    if best is not None:
                        best[1].remove()
                    best = (cost, note, box)
                else:
                    note.remove()
                if cost == 0.0:
                    break
            if best[0] == 0.0:
                break
        taken.append(best[2])


def marker_boxes(panel, groups):
    """Pixel boxes of the markers (and the knee's ring), which no label may cover."""
    boxes = []
    for g in groups:
        r = 9.0 if g.get("knee") else 4.0
        boxes.append(Bbox.from_extents(g["px"] - r, g["py"] - r, g["px"] + r, g["py"] + r))
    return boxes


def line_boxes(panel, levels):
    """Thin pixel boxes along the panel's horizontal lines (budget, tolerance), which labels
    avoid where they can."""
    frame = panel.get_window_extent()
    boxes = []
    for level in levels:
        y = panel.transData.transform((1.0, level))[1]
        boxes.append(Bbox.from_extents(frame.x0, y - 2.0, frame.x1, y + 2.0))
    return boxes


def draw_panel(panel, name, rows, args, floor, first):
    """One figure's panel: the points, the knee, the budget and the round-off tolerance."""
    points = [r for r in rows if r["figure"] == name and r["status"] == "completed"
              and r["change"] not in ("", "inf", "-inf")]
    labelled, knees = [], []
    for r in points:
        change = max(abs(float(r["change"])), floor)
        inside = r["within_budget"] == "1"
        member = r.get("noise_member") not in (None, "", "0")
        panel.scatter(float(r["elapsed_s"]), change, color="C0" if inside else "0.6",
                      marker="x" if member else "o", zorder=3)
        if r["knee"] == "1":
            panel.scatter(float(r["elapsed_s"]), change, s=160, facecolors="none",
                          edgecolors="C3", linewidths=1.5, zorder=4, label="knee")
            knees.append((float(r["elapsed_s"]), change))
        labelled.append((float(r["elapsed_s"]), change, r["label"], inside))
    panel.axhline(args.budget, color="C3", linestyle="--", linewidth=1, label="budget")
    levels = [args.budget]
    tolerances = {float(r["tolerance"]) for r in points if r.get("tolerance")}
    if tolerances and max(tolerances) > args.budget:
        panel.axhline(max(tolerances), color="C1", linestyle=":", linewidth=1.2,
                      label="2 sigma of round-off")
        levels.append(max(tolerances))
    panel.set_xscale("log")
    panel.set_yscale("log")
    # Seconds as plain numbers (200, not 2x10^2); matplotlib picks which minor ticks to label.
    panel.xaxis.set_major_formatter(LogFormatter())
    panel.xaxis.set_minor_formatter(LogFormatter(labelOnlyBase=False, minor_thresholds=(1, 0.4)))
    panel.set_title(name, fontsize=9)
    panel.set_xlabel("elapsed time (s)")
    panel.set_ylabel("|change| against the most accurate run")
    if first:
        panel.legend(fontsize=7, loc="lower left")
    return labelled, knees, levels


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
    fig, axes = plt.subplots(lines, columns, figsize=(4.6 * columns, 3.8 * lines), squeeze=False,
                             layout="constrained")
    drawn, lines_of = [], {}
    for index, (panel, name) in enumerate(zip(axes.flat, figures)):
        labelled, knees, lines_of[panel] = draw_panel(panel, name, rows, args, floor, index == 0)
        drawn.append((panel, labelled, knees))
    for panel in list(axes.flat)[len(figures):]:
        panel.axis("off")
    fig.suptitle("runs labelled " + ", ".join(axes_keys) + f"; floor = change < {floor:g}",
                 fontsize=8)
    # The labels go where the final layout puts the panels: lay out, then freeze the layout.
    fig.canvas.draw()
    fig.set_layout_engine("none")
    renderer = fig.canvas.get_renderer()
    for panel, labelled, knees in drawn:
        groups = groups_of(labelled, panel)
        for g in groups:
            g["knee"] = any(abs(g["px"] - panel.transData.transform(k)[0]) <= 12
                            and abs(g["py"] - panel.transData.transform(k)[1]) <= 12
                            for k in knees)
        taken = marker_boxes(panel, groups) + line_boxes(panel, lines_of[panel])
        legend = panel.get_legend()
        if legend is not None:
            taken.append(legend.get_window_extent(renderer))
        place_labels(fig, panel, groups, taken)
    fig.savefig(args.out, metadata={"Date": None})
    return 0


if __name__ == "__main__":
    sys.exit(main())
