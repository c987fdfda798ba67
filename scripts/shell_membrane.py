"""Membrane forces of a shell of revolution as membrane theory reads them: per element the hoop
force N_theta (round the axis) and the meridional force, with the element's centre and the
contact pressure the sand put on it.

A frame's `membrane_force` is (N11, N22, N12) in each element's centre frame, axis 1 along its
first edge (docs/user-guide/fem.md, "Output"), so which of N11 and N22 is the hoop force depends
on how the mesher ordered the element's corners: read here from the first edge's direction.
cases/silo_janssen/analyse.py and cases/silo_hopper/analyse_shell.py read their shells here.
"""

import numpy as np
from vtk.util.numpy_support import vtk_to_numpy


def hoop_and_meridional(shell, axis):
    """Element centres (n x 3), N_theta, the meridional force N_m (N/m) and the contact pressure
    (Pa) of a shell block whose axis of revolution is the coordinate axis `axis` (0, 1, 2)
    through the origin."""
    points = vtk_to_numpy(shell.GetPoints().GetData())
    membrane = vtk_to_numpy(shell.GetCellData().GetArray("membrane_force"))
    pressure = vtk_to_numpy(shell.GetCellData().GetArray("contact_pressure"))
    unit_axis = np.eye(3)[axis]
    centres = np.empty((shell.GetNumberOfCells(), 3))
    hoop = np.empty(len(centres))
    meridional = np.empty(len(centres))
    for cell in range(len(centres)):
        ids = shell.GetCell(cell).GetPointIds()
        corners = points[[ids.GetId(k) for k in range(ids.GetNumberOfIds())]]
        centres[cell] = corners.mean(axis=0)
        first = corners[1] - corners[0]
        round_axis = np.cross(unit_axis, centres[cell])
        # The first edge runs round the axis (|cos| > 0.7) or along a meridian (|cos| near 0).
        scale = np.linalg.norm(first) * np.linalg.norm(round_axis)
        along_hoop = abs(first @ round_axis) > 0.7 * scale
        hoop[cell] = membrane[cell, 0] if along_hoop else membrane[cell, 1]
        meridional[cell] = membrane[cell, 1] if along_hoop else membrane[cell, 0]
    return centres, hoop, meridional, pressure
