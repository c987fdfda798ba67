#!/usr/bin/python3
"""Speed/accuracy trade of the plane-strain column collapse: stiffness and spacing.

Usage:
    /usr/bin/python3 cases/column_collapse_2d/stiffness_trade.py GRAINLOAD OUT_DIR
        [--runs 1:2,0.1:2,0.01:2,0.001:2,1:4,1:1] [--threads 1] [--analyse-only]

Each run is FACTOR:SPACING_MM. FACTOR scales Young's modulus of column_collapse_2d.toml (so
both the bulk and the shear modulus, at fixed Poisson ratio) and, with it, the wall contact
stiffness: the contact stiffness is not in the CFL step, so it must stay at the material's
scale to stay stable (docs/theory/sph.md, "Wall contact"). The step grows as 1/sqrt(FACTOR).
Runs already in OUT_DIR/E<FACTOR>_dp<SPACING>mm are reused. Prints and writes
OUT_DIR/stiffness_trade.csv: wall time, steps, final height, run-out, heap angle, failure line
and time to
rest, and their change against the first run (the reference). Run-out is given two ways: L_inf
(the bulk's last particle) and L_5% (where the deposit is still 5 % of H0 deep; analyse.front_at).
"""

import argparse
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import analyse  # noqa: E402

CASE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "column_collapse_2d.toml")
YOUNGS_MODULUS_MPA = 5.84
WIDTH_MM, HEIGHT_MM = 200.0, 100.0


def overrides(factor, dp_mm):
    modulus = f"{YOUNGS_MODULUS_MPA * factor:.6g} MPa"
    return [f"material[0].youngs_modulus={modulus}", f"sph.contact.stiffness={modulus}"] + \
        analyse.placement_overrides(dp_mm, WIDTH_MM, HEIGHT_MM)


def measure(out):
    d = analyse.deposit(analyse.frame_files(out)[-1])
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    length = d["L0"]
    return {
        "wall_time": summary["wall_time_s"], "steps": summary["steps"], "height": d["H_inf"],
        "runout": (d["L_inf"] - length) / length,
        "front": (analyse.front_at(d["profile"], analyse.THICK_FRACTION * d["H0"]) - length) /
        length,
        "angle": analyse.heap_angle(d["profile"], d["H_inf"]),
        "rest": analyse.rest_time(out, "column"),
        "failure": d["failure"][0] if d["failure"] else None,
    }


def change(value, reference):
    if value is None or reference is None:
        return "n/a"
    return f"{100.0 * (value - reference) / reference:+.1f} %"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("grainload")
    ap.add_argument("out_dir")
    ap.add_argument("--runs", default="1:2,0.1:2,0.01:2,0.001:2,1:4,1:1")
    ap.add_argument("--threads", type=int, default=1)
    ap.add_argument("--analyse-only", action="store_true")
    args = ap.parse_args()
    os.makedirs(args.out_dir, exist_ok=True)
    rows = []
    for item in args.runs.split(","):
        factor, dp_mm = (float(v) for v in item.split(":"))
        out = os.path.join(args.out_dir, f"E{factor:g}_dp{dp_mm:g}mm")
        if not args.analyse_only and not os.path.exists(os.path.join(out, "summary.json")):
            analyse.run_case(args.grainload, CASE, out, args.threads, overrides(factor, dp_mm))
        rows.append((factor, dp_mm, measure(out)))
    ref = rows[0][2]
    header = ("E factor,spacing_mm,wall_time_s,steps,final_height_m,runout_normalised,"
              "front_5pct_normalised,heap_angle_deg,failure_line_deg,time_to_rest_s,height_change,runout_change,"
              "front_change,angle_change")
    lines = [header]
    for factor, dp_mm, m in rows:
        lines.append(
            f"{factor:g},{dp_mm:g},{m['wall_time']:.1f},{m['steps']},{m['height']:.4f},"
            f"{m['runout']:.4f},{m['front']:.4f},"
            f"{m['angle'] if m['angle'] is None else round(m['angle'], 2)},"
            f"{m['failure'] if m['failure'] is None else round(m['failure'], 1)},{'not at rest' if m['rest'] is None else round(m['rest'], 3)},"
            f"{change(m['height'], ref['height'])},{change(m['runout'], ref['runout'])},"
            f"{change(m['front'], ref['front'])},{change(m['angle'], ref['angle'])}")
    print("\n".join(lines))
    with open(os.path.join(args.out_dir, "stiffness_trade.csv"), "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
