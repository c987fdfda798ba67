#!/usr/bin/python3
"""Analyse plane-wedge hopper discharge runs (cases/hopper_discharge).

Usage:
    /usr/bin/python3 cases/hopper_discharge/analyse.py OUT_DIR [OUT_DIR ...] [--open 0.4]
        [--svg FILE] [--label LABEL ...]

For each run reads OUT_DIR/discharge.csv (one sink) and OUT_DIR/summary.json and prints:
  * the fill's mass (initial plus created by a source), the discharged mass fraction at the
    end, the time after the gate opened (--open, s; default the run's settle_time when its gate
    went on settling, else the placed fill's remove_at, 0.4 s) at which 50 %, 90 % and 99 % were
    out;
  * the steady rate the run fitted (least squares over 20-80 % of the discharged mass) and the
    time to empty at that rate;
  * Beverloo's slot law per metre of slot length, W/L = C' rho_b sqrt(g) (B - k d)^(3/2),
    C' = 1.03, rho_b = 300 kg/m^3, B = 0.4 m, d = 0.065 m (Myers & Sellers; Nedderman
    1992), for k = 0, 1, 1.5 and 3, and the run's rate against each.
With --svg, plots the discharged mass fraction against the time after opening for every run,
with the paper's "empty at about 1.8 s" (Markauskas, Fig. 13, spheres) and the
Beverloo lines (fraction = W t / M0 from the first run's initial mass, starting at the first
arrival at the sink) for k = 1.5 and k = 0.
"""

import csv
import json
import math
import sys

RHO_B = 300.0
B = 0.4
D = 0.065
G = 9.81
C_SLOT = 1.03
PAPER_EMPTY = 1.8


def beverloo(k):
    return C_SLOT * RHO_B * math.sqrt(G) * (B - k * D) ** 1.5


def read_run(out):
    times, masses = [], []
    with open(out + "/discharge.csv") as f:
        for row in csv.DictReader(f):
            times.append(float(row["time_s"]))
            masses.append(float([v for k, v in row.items() if k.startswith("discharged")][0]))
    with open(out + "/summary.json") as f:
        summary = json.load(f)
    return times, masses, summary


def opened_at(results):
    """When the orifice opened: the settle time of a run whose gate goes when the fill settles
    (hopper_deposition*.toml), else the placed fill's fixed 0.4 s."""
    settled = results.get("settle_time", {}).get("value")
    return settled if settled is not None else 0.4


def first_time(times, fractions, level):
    for t, f in zip(times, fractions):
        if f >= level:
            return t
    return float("nan")


def main(argv):
    runs, labels, svg, opening = [], [], None, None
    k = 0
    while k < len(argv):
        if argv[k] == "--svg":
            svg = argv[k + 1]
            k += 2
        elif argv[k] == "--open":
            opening = float(argv[k + 1])
            k += 2
        elif argv[k] == "--label":
            labels.append(argv[k + 1])
            k += 2
        else:
            runs.append(argv[k])
            k += 1
    if not runs:
        print(__doc__)
        return 2
    print("Beverloo slot law per metre: " +
          ", ".join("k = %g: %.0f kg/m/s" % (kk, beverloo(kk)) for kk in (0, 1, 1.5, 3)))
    curves = []
    for i, out in enumerate(runs):
        times, masses, summary = read_run(out)
        results = summary["results"]
        m0 = results["initial_mass"]["value"] + results.get("created_mass", {}).get("value", 0.0)
        fractions = [m / m0 for m in masses]
        opened = opening if opening is not None else opened_at(results)
        after = [t - opened for t in times]
        rate = results["sink_below_steady_rate"]["value"]
        label = labels[i] if i < len(labels) else out
        print("%s: M0 = %.2f kg/m, %.1f %% out at the end; 50/90/99 %% out %.2f / %.2f / %.2f s "
              "after opening; steady rate %.1f kg/m/s (window %.2f-%.2f s), empty at that rate "
              "in %.2f s; rate / Beverloo k=1.5: %.2f, k=0: %.2f; wall time %.1f s"
              % (label, m0, 100 * fractions[-1], first_time(after, fractions, 0.5),
                 first_time(after, fractions, 0.9), first_time(after, fractions, 0.99), rate,
                 results["sink_below_steady_window_start"]["value"],
                 results["sink_below_steady_window_end"]["value"], m0 / rate,
                 rate / beverloo(1.5), rate / beverloo(0.0), summary["wall_time_s"]))
        curves.append((label, after, fractions, m0))
    if svg:
        import matplotlib
        matplotlib.use("Agg")
        matplotlib.rcParams["svg.hashsalt"] = "grainload"  # the same runs draw the same file
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(6.5, 4.2))
        for label, after, fractions, _ in curves:
            ax.plot(after, fractions, marker=".", label=label)
        m0 = curves[0][3]
        # The lines start where the streams first reach the sink (the earliest arrival of any
        # run), so that their slopes compare with the curves'.
        start = min(t for _, after, fractions, _ in curves
                    for t, f in zip(after, fractions) if f > 0)
        for kk, style in ((1.5, ":"), (0.0, "--")):
            w = beverloo(kk)
            ax.plot([start, start + m0 / w], [0, 1], "k" + style, lw=1,
                    label="Beverloo slot, k = %g (%.0f kg/m/s)" % (kk, w))
        ax.axvline(PAPER_EMPTY, color="r", lw=1, label="paper (DEM spheres): empty at 1.8 s")
        ax.set_xlim(0, max(c[1][-1] for c in curves))
        ax.set_ylim(0, 1.05)
        ax.set_xlabel("time after the orifice opened (s)")
        ax.set_ylabel("discharged mass fraction")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8, loc="lower right")
        fig.tight_layout()
        fig.savefig(svg, metadata={"Date": None})
        print("wrote " + svg)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
