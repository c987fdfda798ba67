#!/usr/bin/python3
"""Peak displacement and von Mises stress of each shell block of a grainload frame, and where:
/usr/bin/python3 shell_peaks.py FRAME.vtm [--away X Y Z R ...]

For wagon_pressure.toml: out/wagon_pressure/frames/wagon_pressure_000001.vtm (the last frame).
Per shell block (one per [[fem.shell]] part): the node of the largest |displacement| and the
element of the largest von Mises stress (the largest of von_mises_top, _middle, _bottom), with
their undeformed positions; --away X Y Z R (m, repeatable) also gives the peak stress of the
elements whose centre is farther than R from the point (X, Y, Z), e.g. away from a stress
concentration. Reads the frame with VTK's Python bindings (python3-vtk9).
"""
import argparse

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLMultiBlockDataReader


def shell_blocks(frame):
    reader = vtkXMLMultiBlockDataReader()
    reader.SetFileName(frame)
    reader.Update()
    data = reader.GetOutput()
    for i in range(data.GetNumberOfBlocks()):
        block = data.GetBlock(i)
        if block is not None and block.IsA("vtkUnstructuredGrid"):
            yield data.GetMetaData(i).Get(data.NAME()), block


def block_peaks(grid, away):
    u = vtk_to_numpy(grid.GetPointData().GetArray("displacement"))
    origin = vtk_to_numpy(grid.GetPoints().GetData()) - u
    node = int(np.argmax(np.linalg.norm(u, axis=1)))
    cells = grid.GetCellData()
    stress = np.max([vtk_to_numpy(cells.GetArray("von_mises_" + s))
                     for s in ("top", "middle", "bottom")], axis=0)
    thickness = vtk_to_numpy(cells.GetArray("thickness"))
    centres = np.array([origin[[grid.GetCell(e).GetPointId(k)
                                for k in range(grid.GetCell(e).GetNumberOfPoints())]].mean(axis=0)
                        for e in range(grid.GetNumberOfCells())])

    def peak(elements):
        e = elements[int(np.argmax(stress[elements]))]
        return f"{stress[e] / 1e6:.1f} MPa at {fmt(centres[e])} (thickness {thickness[e] * 1e3:.0f} mm)"

    lines = [f"peak |u| {np.linalg.norm(u[node]) * 1e3:.2f} mm at {fmt(origin[node])}, "
             f"u = ({', '.join(f'{v * 1e3:.2f}' for v in u[node])}) mm",
             f"peak von Mises {peak(np.arange(len(stress)))}"]
    if away:
        far = np.ones(len(stress), dtype=bool)
        for x, y, z, r in away:
            far &= np.linalg.norm(centres - np.array([x, y, z]), axis=1) > r
        lines.append(f"peak von Mises away from the given points {peak(np.flatnonzero(far))}")
    return lines


def fmt(x):
    return "(" + ", ".join(f"{v:.3f}" for v in x) + ") m"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("frame")
    parser.add_argument("--away", nargs=4, type=float, action="append", default=[],
                        metavar=("X", "Y", "Z", "R"))
    args = parser.parse_args()
    for name, grid in shell_blocks(args.frame):
        print(f"{name}: " + "; ".join(block_peaks(grid, args.away)))


if __name__ == "__main__":
    main()
