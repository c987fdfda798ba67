#!/usr/bin/env python3
"""Writes the gold files of small cases: every figure of a run's summary.json, with its tolerance.

usage: scripts/update_gold.py [--grainload PATH] [--spread] CASE.toml [CASE.toml ...]

Each case runs with `OMP_NUM_THREADS=1 grainload run CASE --threads 1` in a copy of its folder
(so that a mesh Gmsh makes does not land in the source tree): one thread for the SPH sums and
for the BLAS under the shells' sparse solver, whose AVX2 kernels (OPENBLAS_CORETYPE=Haswell,
where the CPU has AVX2, as the tests pin them) repeat themselves bit for bit on any machine.
Its figures go to cases/<folder>/gold/<case>.json: {"case", "command", "figures": {name:
{"value", "unit", "tolerance"}}}. A figure keeps the tolerance name its gold file already gives
it; a new one gets "round_off". The names and their bounds are those of
tests/support/tolerances.hpp; the figures that depend on the machine (threads, wall time, rates
per second) are left out as tests/support/gold_summary.hpp lists them. --spread runs each case
on 2 threads as well (OMP_NUM_THREADS=2 --threads 2) and prints how far each figure moved,
against the bound of its tolerance.
"""

import argparse
import json
import math
import os
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent
TOLERANCES = ROOT / "tests/support/tolerances.hpp"
GOLD_CHECK = ROOT / "tests/support/gold_summary.hpp"
DEFAULT_TOLERANCE = "round_off"


def tolerances():
    """{name: (relative, absolute)} as tests/support/tolerances.hpp defines them."""
    text = TOLERANCES.read_text()
    entries = re.findall(r'\{"(\w+)", ([-+0-9.eE]+), ([-+0-9.eE]+)\}', text)
    return {name: (float(rel), float(abs_)) for name, rel, abs_ in entries}


def machine_figures():
    """The names of kMachineFigures in tests/support/gold_summary.hpp."""
    text = GOLD_CHECK.read_text()
    block = re.search(r"kMachineFigures = \{(.*?)\};", text, re.S)
    return set(re.findall(r'"(\w+)"', block.group(1)))


def figures(summary, machine):
    """[(name, value, unit)]: top-level numbers other than the machine's, then the results."""
    out = [(name, value, "") for name, value in summary.items()
           if isinstance(value, (int, float)) and not isinstance(value, bool)
           and name not in machine]
    for name, figure in summary.get("results", {}).items():
        out.append((name, figure.get("value"), figure.get("unit", "")))
    return out


def cpu_flags():
    """The CPU's feature flags as /proc/cpuinfo lists them ("" where it cannot be read)."""
    try:
        for line in pathlib.Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("flags"):
                return line.split(":", 1)[1]
    except OSError:
        pass
    return ""


def run_case(grainload, case, threads, scratch):
    """Runs `case` on `threads` threads in a copy of its folder; returns its summary."""
    copy = pathlib.Path(scratch) / f"{case.stem}_{threads}"
    shutil.copytree(case.parent, copy, ignore=shutil.ignore_patterns("gold", "out"))
    out = copy / "out"
    command = [str(grainload), "run", str(copy / case.name), "--threads", str(threads),
               "--out", str(out)]
    # --threads sets the BLAS threads of the shells' factorisation too; OMP_NUM_THREADS holds
    # any library the run does not set.
    env = dict(os.environ, OMP_NUM_THREADS=str(threads))
    # OpenBLAS's AVX2 kernels where the CPU has AVX2, as the tests pin them
    # (tests/support/cli_runner.hpp): a packing on a coupled shell amplifies the last bits in
    # which the kernel sets differ.
    if " avx2 " in f" {cpu_flags()} ":
        env["OPENBLAS_CORETYPE"] = "Haswell"
    result = subprocess.run(command, capture_output=True, text=True, env=env)
    if result.returncode != 0:
        sys.exit(f"{case}: grainload exited with {result.returncode}\n{result.stdout}"
                 f"{result.stderr}")
    return json.loads((out / "summary.json").read_text())


def gold_file(case):
    return case.parent / "gold" / (case.stem + ".json")


def write_gold(path, gold):
    """The gold file, one figure a line, so that a change shows as the lines of its figures."""
    path.parent.mkdir(exist_ok=True)
    lines = [f"    {json.dumps(name)}: {json.dumps(entry)}"
             for name, entry in gold["figures"].items()]
    path.write_text("{\n" + f'  "case": {json.dumps(gold["case"])},\n'
                    f'  "command": {json.dumps(gold["command"])},\n'
                    '  "figures": {\n' + ",\n".join(lines) + "\n  }\n}\n")


def print_spread(case, one, two, kept, bounds):
    """How far each figure moved from 1 to 2 threads, against the bound of its tolerance."""
    values = {name: value for name, value, _ in two}
    print(f"{case}: 1 thread -> 2 threads")
    for name, value, _ in one:
        other = values.get(name)
        tolerance = kept.get(name, DEFAULT_TOLERANCE)
        if value is None or other is None:
            print(f"  {name:40s} {value} -> {other}")
            continue
        off = abs(other - value)
        relative = off / abs(value) if value != 0 else math.inf if off else 0.0
        rel, abs_ = bounds[tolerance]
        verdict = "ok" if off <= abs_ + rel * abs(value) else "EXCEEDS"
        print(f"  {name:40s} {value:.12g} -> {other:.12g}: {off:.3g} ({relative:.3g} relative),"
              f" {tolerance} {verdict}")


def update(case, grainload, spread, machine, bounds, scratch):
    relative = case.resolve().relative_to(ROOT)
    path = gold_file(case.resolve())
    kept = {}
    if path.exists():
        kept = {name: entry["tolerance"]
                for name, entry in json.loads(path.read_text())["figures"].items()}
    one = figures(run_case(grainload, case.resolve(), 1, scratch), machine)
    if spread:
        two = figures(run_case(grainload, case.resolve(), 2, scratch), machine)
        print_spread(relative, one, two, kept, bounds)
    entries = {}
    for name, value, unit in one:
        tolerance = kept.get(name, DEFAULT_TOLERANCE)
        if tolerance not in bounds:
            sys.exit(f"{path}: tolerance '{tolerance}' of '{name}' is not in {TOLERANCES}")
        entries[name] = {"value": value, "unit": unit, "tolerance": tolerance}
    write_gold(path, {"case": str(relative),
                      "command": f"OMP_NUM_THREADS=1 grainload run {relative} --threads 1",
                      "figures": entries})
    print(f"{path.relative_to(ROOT)}: {len(entries)} figures")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("cases", nargs="+", type=pathlib.Path, help="small case files")
    parser.add_argument("--grainload", type=pathlib.Path, default=ROOT / "build/app/grainload")
    parser.add_argument("--spread", action="store_true",
                        help="also run on 2 threads and print how far each figure moved")
    args = parser.parse_args()
    bounds = tolerances()
    machine = machine_figures()
    with tempfile.TemporaryDirectory(prefix="grainload_gold_") as scratch:
        for case in args.cases:
            update(case, args.grainload, args.spread, machine, bounds, scratch)


if __name__ == "__main__":
    main()
