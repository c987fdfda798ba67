"""The frames of a grainload run: the .pvd index of its output directory and the named blocks
of each frame's .vtm multiblock (VTK's Python bindings, python3-vtk9).

scripts/render_frames.py, cases/hopper_wagon/analyse_discharge.py, cases/silo_hopper/analyse.py and
cases/silo_hopper/analyse_shell.py read their frames here.
"""

import os
import sys
import xml.etree.ElementTree as ElementTree

from vtkmodules.vtkIOXML import vtkXMLMultiBlockDataReader


def frames_of(out_dir):
    """(time, .vtm path) of every frame listed in the run's .pvd."""
    pvd = [name for name in os.listdir(out_dir) if name.endswith(".pvd")]
    if len(pvd) != 1:
        sys.exit(f"{os.path.basename(sys.argv[0])}: expected one .pvd in {out_dir}, found {len(pvd)}")
    root = ElementTree.parse(os.path.join(out_dir, pvd[0])).getroot()
    return [(float(d.get("timestep")), os.path.join(out_dir, d.get("file")))
            for d in root.iter("DataSet")]


def blocks(vtm_path):
    """(name, dataset) of each of the frame's blocks, in the file's order; the dataset of a
    body without points (a source not yet filled, a load that has left) may be None."""
    reader = vtkXMLMultiBlockDataReader()
    reader.SetFileName(vtm_path)
    reader.Update()
    data = reader.GetOutput()
    return [(data.GetMetaData(index).Get(data.NAME()), data.GetBlock(index))
            for index in range(data.GetNumberOfBlocks())]
