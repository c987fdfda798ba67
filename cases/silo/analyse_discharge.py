#!/usr/bin/python3
"""Analyse a slot-silo discharge run (cases/silo/silo_discharge_small.toml).

Usage:
    /usr/bin/python3 cases/silo/analyse_discharge.py OUT [--outlet 0.2] [--png FILE]

Reads OUT/wall_maps/rest_window.csv and flow_window.csv (the right wall's pressure at rest
before the outlet opens and during the discharge, [[sph.wall_map]]), OUT/discharge.csv and
OUT/summary.json, and prints:
  * per 0.2 m bin: p_h at rest, the discharge's mean and maximum (of 0.1 s interval means),
    their ratios to the rest value, and EN 1991-4's discharge factor for slender silos, 1.15;
  * the steady discharge rate against Beverloo's slot law per metre, W = C' rho_b sqrt(g)
    (B - k d)^(3/2), C' = 1.03, rho_b = 1500 kg/m^3 (Myers & Sellers; Nedderman 1992),
    with B the effective outlet (--outlet, m) and k d = 0 (a continuum has no grain size).
Writes OUT/silo_discharge.png (or --png): the pressure profiles and the discharged mass.
"""

import csv
import json
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

RHO_B = 1500.0
G = 9.81
C_SLOT = 1.03
EN_DISCHARGE = 1.15


def rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def main(argv):
    out, outlet, png = argv[0], 0.2, None
    k = 1
    while k < len(argv):
        if argv[k] == "--outlet":
            outlet, k = float(argv[k + 1]), k + 2
        elif argv[k] == "--png":
            png, k = argv[k + 1], k + 2
        else:
            sys.exit("unknown argument " + argv[k])
    rest = rows(out + "/wall_maps/rest_window.csv")
    flow = rows(out + "/wall_maps/flow_window.csv")
    with open(out + "/summary.json") as f:
        whole = json.load(f)
    summary = whole["results"]
    print("window at rest %s-%s s, discharge %s-%s s" % (rest[0]["window_start_s"],
          rest[0]["window_end_s"], flow[0]["window_start_s"], flow[0]["window_end_s"]))
    print("| height (m) | p_h rest (Pa) | discharge mean | discharge max | mean / rest | "
          "max / rest |")
    print("| --- | --- | --- | --- | --- | --- |")
    heights, p_rest, p_mean, p_max = [], [], [], []
    for a, b in zip(rest, flow):
        heights.append(float(a["u_m"]))
        p_rest.append(float(a["mean_pressure_Pa"]))
        p_mean.append(float(b["mean_pressure_Pa"]))
        p_max.append(float(b["max_pressure_Pa"]))
        if p_rest[-1] > 100.0:
            print("| %.1f | %.0f | %.0f | %.0f | %.2f | %.2f |" % (
                heights[-1], p_rest[-1], p_mean[-1], p_max[-1], p_mean[-1] / p_rest[-1],
                p_max[-1] / p_rest[-1]))
    rate = summary["sink_below_steady_rate"]["value"]
    beverloo = C_SLOT * RHO_B * math.sqrt(G) * outlet ** 1.5
    print("steady rate %.1f kg/m/s over %.2f-%.2f s; Beverloo (B = %.3f m, k d = 0) %.1f "
          "kg/m/s; ratio %.2f" % (rate, summary["sink_below_steady_window_start"]["value"],
                                  summary["sink_below_steady_window_end"]["value"], outlet,
                                  beverloo, rate / beverloo))
    print("discharged %.1f kg/m of %.1f kg/m created; mass audit %g; wall time %.1f s" % (
        summary["discharged_mass"]["value"], summary["created_mass"]["value"],
        summary["mass_audit_error"]["value"], whole["wall_time_s"]))

    figure, axes = plt.subplots(1, 2, figsize=(11, 4.5))
    axes[0].plot(p_rest, heights, "o-", label="at rest")
    axes[0].plot([EN_DISCHARGE * p for p in p_rest], heights, "k--",
                 label="1.15 x at rest (EN 1991-4)")
    axes[0].plot(p_mean, heights, "s-", label="discharge, mean")
    axes[0].plot(p_max, heights, "^-", label="discharge, max of 0.1 s means")
    axes[0].set_xlabel("wall pressure p_h (Pa)")
    axes[0].set_ylabel("height above the floor (m)")
    axes[0].grid(True)
    axes[0].legend(fontsize="small")
    discharge = rows(out + "/discharge.csv")
    axes[1].plot([float(r["time_s"]) for r in discharge],
                 [float([v for k, v in r.items() if k.startswith("discharged")][0])
                  for r in discharge], "o-", label="run")
    axes[1].set_xlabel("time (s)")
    axes[1].set_ylabel("discharged mass (kg/m)")
    axes[1].grid(True)
    figure.tight_layout()
    png = png or out + "/silo_discharge.png"
    figure.savefig(png, dpi=100)
    print(png)


if __name__ == "__main__":
    main(sys.argv[1:])
