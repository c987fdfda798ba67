#!/usr/bin/python3
"""Tabulate slot-silo closure runs (cases/silo/silo_closure*.toml) side by side.

Usage:
    /usr/bin/python3 cases/silo/analyse_closure.py OUT [OUT ...] [--label NAME ...]

For each run directory, from OUT/summary.json and the right wall's maps
(OUT/wall_maps/{rest,flow,closure}_window.csv, 0.2 m bins from the floor) prints one row of
the closure's spacing study in docs/validation/silo.md: particles, steps, wall time, steady
rate, discharged mass, the bottom bin's pressure at rest (window mean), the discharge's peak
(largest 20 ms interval mean, any bin), the closure's largest interval mean in the bottom two
bins, the bottom bin's mean over the closure window, its ratio to the rest value, the bound
rest + rho c v of an elastic column's arrest (rho = 1500 kg/m^3, c the P-wave speed of the
sand scaled by stiffness_scale, v = W / (rho B) with W the run's steady rate and B = 0.5 m),
and the energy balance error.
"""

import argparse
import csv
import json
import math
import sys

RHO = 1500.0
WIDTH = 0.5  # m between the silo's walls
E, NU = 5e6, 0.3  # the case's sand (silo_closure*.toml)


def window(path):
    with open(path) as f:
        return {round(float(r["u_m"]), 3): r for r in csv.DictReader(f)}


def value(summary, name):
    return summary["results"][name]["value"]


def row(out, label):
    with open(out + "/summary.json") as f:
        summary = json.load(f)
    rest = window(out + "/wall_maps/rest_window.csv")
    closure = window(out + "/wall_maps/closure_window.csv")
    scale = 1.0  # the run's --set material[0].stiffness_scale, if any
    for assignment in summary.get("overrides", []):
        if assignment.startswith("material[0].stiffness_scale="):
            scale = float(assignment.split("=", 1)[1])
    p_wave = math.sqrt(E * (1 - NU) / ((1 + NU) * (1 - 2 * NU)) * scale / RHO)
    rate = value(summary, "sink_below_steady_rate")
    bound = float(rest[0.1]["mean_pressure_Pa"]) + RHO * p_wave * rate / (RHO * WIDTH)
    rest0 = float(rest[0.1]["mean_pressure_Pa"])
    peaks = "%.0f / %.0f" % (float(closure[0.1]["max_pressure_Pa"]),
                             float(closure[0.3]["max_pressure_Pa"]))
    mean0 = float(closure[0.1]["mean_pressure_Pa"])
    return ("| %s | %d | %d | %.0f s | %.1f | %.2f | %.0f | %.0f | %s | %.0f | %.2f | %.0f | %.2g |"
            % (label, summary["particles"], summary["steps"], summary["wall_time_s"], rate,
               value(summary, "sink_below_discharged_mass"), rest0,
               value(summary, "wall_map_flow_peak_max_pressure"), peaks, mean0, mean0 / rest0,
               bound, value(summary, "energy_balance_error")))


def main(argv):
    parser = argparse.ArgumentParser(description="slot-silo closure runs side by side")
    parser.add_argument("outs", nargs="+", help="run directories")
    parser.add_argument("--label", action="append", default=[], help="a name per run, in order")
    args = parser.parse_args(argv)
    outs, labels = args.outs, args.label + args.outs[len(args.label):]
    print("| run | particles | steps | wall time | steady rate (kg/m/s) | discharged (kg/m) | "
          "rest, bottom bin (Pa) | discharge peak (Pa) | closure max, 0-0.2 / 0.2-0.4 m (Pa) | "
          "closure mean, bottom bin (Pa) | closure mean / rest | rest + rho c v (Pa) | "
          "energy error |")
    print("| --- " * 13 + "|")
    for out, label in zip(outs, labels):
        print(row(out, label))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
