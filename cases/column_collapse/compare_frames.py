#!/usr/bin/env python3
"""Frame-by-frame comparison of two runs of the same column-collapse case (same particles, same
numbering), e.g. the thesis stiffness against its K/1000 equivalent, for
docs/validation/column_collapse.md. For every frame both runs have: the highest particle
centre, the 99th percentile of the distance from the column's axis, and how far each particle
of run A is from the same particle of run B (RMS, median and largest).
Usage (ParaView's or Debian's python3-vtk9):
  /usr/bin/python3 compare_frames.py RUN_A RUN_B CASE_NAME [FRAME_INTERVAL_S]"""
import os
import sys

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy


def body_positions(path):
    """Particle centres (n x 3, m) of a frame: the first block of a .vtm, or a body's .vtp."""
    vtp = path.endswith(".vtp")
    reader = vtk.vtkXMLPolyDataReader() if vtp else vtk.vtkXMLMultiBlockDataReader()
    reader.SetFileName(path)
    reader.Update()
    data = reader.GetOutput() if vtp else reader.GetOutput().GetBlock(0)
    return vtk_to_numpy(data.GetPoints().GetData())


def main():
    run_a, run_b, name = sys.argv[1:4]
    interval = float(sys.argv[4]) if len(sys.argv) > 4 else 0.05
    print("| t (s) | top A / B (mm) | r99 A / B (mm) | RMS | median | largest (mm) |")
    print("| --- | --- | --- | --- | --- | --- |")
    k = 0
    while True:
        frames = [f"{run}/frames/{name}_{k:06d}.vtm" for run in (run_a, run_b)]
        if not all(os.path.exists(f) for f in frames):
            break
        a, b = (body_positions(f) for f in frames)
        gap = np.linalg.norm(a - b, axis=1) * 1e3
        r99 = [np.percentile(np.hypot(x[:, 0], x[:, 1]), 99) * 1e3 for x in (a, b)]
        print(f"| {k * interval:.2f} | {a[:, 2].max() * 1e3:.1f} / {b[:, 2].max() * 1e3:.1f} "
              f"| {r99[0]:.1f} / {r99[1]:.1f} | {np.sqrt((gap ** 2).mean()):.3f} "
              f"| {np.median(gap):.3f} | {gap.max():.2f} |")
        k += 1


if __name__ == "__main__":
    main()
