#!/usr/bin/env python3
"""The cost estimate of `grainload check` against the run, case by case, as a markdown table.

Each case is run with `grainload run CASE --out OUT/NAME --threads N` (one at a time); its
summary.json holds the estimate the run made before its first step (app/cost_estimate.hpp) and
what the run took. The table gives, per case: the steps estimated and taken, the wall time
estimated and taken and their ratio (actual / estimate), the run's CPU time over the same span
and its ratio to the estimate (summary.json cpu_time_s: on a loaded machine the wall time
stretches, the CPU time much less; on one thread of a quiet machine the two agree), the shell's
factorisations estimated and made, the 1-minute load average before the run, and the
calibration the estimate used.

usage: bench/estimate_table.py [--grainload build/app/grainload] [--threads 1]
                               [--out /tmp/estimate_table] [--summaries] CASE.toml ...
  --summaries: do not run; tabulate OUT/NAME/summary.json of earlier runs (their load is then
               unknown, printed as -).
With no case, every shipped case's CI version (cases/*/*_small.toml).
"""

import argparse
import glob
import json
import os
import subprocess
import sys


def load_average():
    with open("/proc/loadavg") as f:
        return float(f.read().split()[0])


def run_case(grainload, case, out, threads):
    """Runs the case into out; returns the 1-minute load average before it."""
    load = load_average()
    with open(out + ".log", "w") as log:
        code = subprocess.call([grainload, "run", case, "--out", out, "--threads", str(threads)],
                               stdout=log, stderr=subprocess.STDOUT)
    if code != 0:
        print(f"{case}: grainload run exited {code} (log {out}.log)", file=sys.stderr)
    return load


def fmt(value, digits=3):
    if value is None:
        return "-"
    if isinstance(value, float) and value >= 100:
        return f"{value:.0f}"
    return f"{value:.{digits}g}"


def row(case, summary, load):
    est = summary.get("estimate", {})
    steps, est_steps = summary.get("steps"), est.get("steps")
    wall, est_wall = summary.get("wall_time_s"), est.get("wall_time_s")
    fact = summary.get("results", {}).get("fem_factorisations", {}).get("value")
    est_fact = est.get("fem_factorisations")
    cells = [
        f"`{case}`",
        f"{fmt(est_steps, 6)} / {fmt(steps, 6)} ({fmt(est.get('steps_ratio'), 4)})",
        f"{fmt(est_wall)} / {fmt(wall)} ({fmt(est.get('wall_time_ratio'))})",
        f"{fmt(summary.get('cpu_time_s'))} ({fmt(est.get('cpu_time_ratio'))})",
        "-" if est_fact is None else f"{fmt(est_fact, 6)} / {fmt(fact, 6)}",
        fmt(load),
        summary.get("threads", "-"),
    ]
    return "| " + " | ".join(str(c) for c in cells) + " |", est.get("calibration", "")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--grainload", default="build/app/grainload")
    parser.add_argument("--threads", type=int, default=1)
    parser.add_argument("--out", default="/tmp/estimate_table")
    parser.add_argument("--summaries", action="store_true")
    parser.add_argument("cases", nargs="*")
    args = parser.parse_args()
    cases = args.cases or sorted(glob.glob("cases/*/*_small.toml"))
    os.makedirs(args.out, exist_ok=True)
    print("| case | steps est. / actual (ratio) | wall time est. / actual, s (ratio) | "
          "CPU time, s (ratio) | factorisations est. / actual | load before | threads |")
    print("| --- | --- | --- | --- | --- | --- | --- |")
    calibrations = set()
    for case in cases:
        name = os.path.splitext(os.path.basename(case))[0]
        out = os.path.join(args.out, name)
        load = None if args.summaries else run_case(args.grainload, case, out, args.threads)
        path = os.path.join(out, "summary.json")
        if not os.path.exists(path):
            print(f"| `{case}` | no summary.json | | | | | |")
            continue
        with open(path) as f:
            line, calibration = row(case, json.load(f), load)
        print(line)
        sys.stdout.flush()
        calibrations.add(calibration)
    for calibration in sorted(calibrations):
        print(f"\ncalibration: {calibration}")


if __name__ == "__main__":
    main()
