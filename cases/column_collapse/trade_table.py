#!/usr/bin/env python3
"""Markdown table of the heap figures of column-collapse runs, for the trade study of
docs/validation/column_collapse.md. Usage: trade_table.py SUMMARY.json [SUMMARY.json ...]
(each a run's summary.json or a kept summary_0.1s.json / summary_0.2s.json)."""
import json
import sys


def figure(results, name, scale=1.0, digits=1):
    value = results.get(name, {}).get("value")
    return "null" if value is None else f"{value * scale:.{digits}f}"


print("| run | t (s) | steps | wall (s) | final height (mm) | run-out (mm) | angle (deg) "
      "| time to rest (s) | outside |")
print("| --- | --- | --- | --- | --- | --- | --- | --- | --- |")
for path in sys.argv[1:]:
    with open(path) as f:
        summary = json.load(f)
    r = summary["results"]
    print(f"| {path} | {summary['simulated_time_s']:.2f} | {summary['steps']} "
          f"| {summary['wall_time_s']:.0f} | {figure(r, 'heap_final_height', 1e3)} "
          f"| {figure(r, 'heap_run_out', 1e3)} | {figure(r, 'heap_angle')} "
          f"| {figure(r, 'heap_time_to_rest', 1.0, 3)} "
          f"| {figure(r, 'heap_particles_outside', 1.0, 0)} |")
