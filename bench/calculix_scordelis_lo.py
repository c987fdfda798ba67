#!/usr/bin/env python3
"""Scordelis-Lo roof in CalculiX (the shell peer) beside grainload's MITC4.

Writes the quarter-roof .inp files with bench/calculix/write_inp.py (S4 shells, the same mesh
and loads as fem/shell_benchmarks.cpp), runs ccx on each, reads the mid-span free-edge
deflection from the .dat file and prints accuracy and wall time next to grainload's bench/shell_solve figures.

Usage: calculix_scordelis_lo.py [--ccx ccx] [--shell-solve build/bench/shell_solve]
                                [--work DIR] [n ...]   (default n = 4 8 16 32 64)
Run from the repository root.
"""
import argparse
import math
import os
import re
import subprocess
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "calculix"))
import write_inp as decks  # noqa: E402  (bench/calculix/write_inp.py writes every peer deck)

REFERENCE = decks.SL_REF


def write_inp(path, n):
    """The quarter-roof S4 deck, from the one deck writer the peer benchmarks share."""
    with open(path, "w") as f:
        decks.scordelis(f, n, "S4")


def run_ccx(ccx, work, n):
    job = os.path.join(work, f"scordelis_lo_s4_{n}")
    write_inp(job + ".inp", n)
    start = time.perf_counter()
    subprocess.run([ccx, "-i", job], cwd=work, check=True, stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL, env=dict(os.environ, OMP_NUM_THREADS="1"))
    seconds = time.perf_counter() - start
    with open(job + ".dat") as f:
        rows = [l.split() for l in f if re.match(r"^\s*\d+\s+[-+0-9.E]+", l)]
    return abs(float(rows[-1][3])), seconds


def run_grainload(shell_solve, largest):
    """Rows of bench/shell_solve for the Scordelis-Lo roof: n -> (value, total seconds)."""
    out = subprocess.run([shell_solve, str(largest)], check=True, capture_output=True,
                         text=True).stdout
    result = {}
    for line in out.splitlines():
        if line.startswith("Scordelis-Lo roof"):
            f = line[len("Scordelis-Lo roof"):].split()
            result[int(f[0])] = (float(f[2]), float(f[5]) + float(f[6]) + float(f[7]))
    return result


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--ccx", default="ccx")
    p.add_argument("--shell-solve", default="build/bench/shell_solve")
    p.add_argument("--work", default="build/calculix_work")  # ignored by git
    p.add_argument("sizes", nargs="*", type=int, default=[4, 8, 16, 32, 64])
    a = p.parse_args()
    os.makedirs(a.work, exist_ok=True)
    ours = run_grainload(a.shell_solve, max(a.sizes)) if os.path.exists(a.shell_solve) else {}
    print(f"{'n':>4} {'ccx S4':>10} {'error':>8} {'ccx s':>8} {'MITC4':>10} {'error':>8} "
          f"{'ours s':>8} {'time ratio':>10}")
    for n in a.sizes:
        value, seconds = run_ccx(a.ccx, os.path.abspath(a.work), n)
        mine, my_seconds = ours.get(n, (math.nan, math.nan))
        print(f"{n:4d} {value:10.5f} {100 * (value / REFERENCE - 1):+7.2f}% {seconds:8.3f} "
              f"{mine:10.5f} {100 * (mine / REFERENCE - 1):+7.2f}% {my_seconds:8.3f} "
              f"{my_seconds / seconds:10.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
