#!/usr/bin/python3
"""Render grainload frames to PNG off screen with VTK's Python bindings (python3-vtk9).

    scripts/render_frames.py OUT --times 0,2.5,11 [--color velocity|von_mises]
                             [--mirror x,y] [--walls door] [--view AZIMUTH,ELEVATION]
                             [--zoom 1.3] [--size 1600x900] [--point 4] [--range LO,HI]
                             [--prefix NAME]

OUT is a run's output directory (its .pvd lists the frames and their times); every time picks
the frame nearest to it. Particle blocks are drawn as spheres coloured by speed |v| (m/s);
shell blocks as surfaces coloured by the von Mises stress, the largest of the top, middle
and bottom surfaces (MPa); wall-particle blocks (`wall_*`) are left out, the shell they
sample is drawn instead. `--color von_mises` greys the particles so the shell stands out.
`--walls door` draws the named wall blocks too, as grey points (a rigid door that swings
open). `--mirror x,y` reflects everything in the planes x = 0 and y = 0, so a quarter model is
shown whole. The pictures go to OUT/pictures/PREFIX_tNNN.png (time in centiseconds).

Without a display (CI, ssh) run it under xvfb-run (package xvfb): `xvfb-run -a python3 ...`.
"""

import argparse
import os
import sys

import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (registers the OpenGL render window)
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkLookupTable
from vtkmodules.vtkFiltersGeneral import vtkReflectionFilter
from vtkmodules.vtkFiltersGeometry import vtkGeometryFilter
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingAnnotation import vtkScalarBarActor
from vtkmodules.vtkRenderingCore import (
    vtkActor,
    vtkPolyDataMapper,
    vtkRenderer,
    vtkRenderWindow,
    vtkTextActor,
    vtkWindowToImageFilter,
)
import numpy as np

from vtk_frames import blocks, frames_of


def mirrored(dataset, planes):
    """The dataset with its reflections in the planes x = 0 / y = 0 (vtkReflectionFilter
    keeps the input and appends the copy, so two planes give four quarters)."""
    for axis in planes:
        reflect = vtkReflectionFilter()
        reflect.SetInputData(dataset)
        reflect.SetPlane(reflect.USE_X if axis == "x" else reflect.USE_Y)
        reflect.SetCenter(0.0)
        reflect.CopyInputOn()
        reflect.Update()
        dataset = reflect.GetOutput()
    return dataset


def surface(dataset):
    geometry = vtkGeometryFilter()
    geometry.SetInputData(dataset)
    geometry.Update()
    return geometry.GetOutput()


def mapper_for(poly, lookup, values=None, name=None, cells=False):
    """A mapper of `poly`, coloured through `lookup` by `values` (a point array, or a cell
    array with cells=True, added to poly as `name`), or plain without values."""
    mapper = vtkPolyDataMapper()
    mapper.SetInputData(poly)
    if values is None:
        mapper.ScalarVisibilityOff()
        return mapper
    array = numpy_to_vtk(values, deep=True)
    array.SetName(name)
    (poly.GetCellData() if cells else poly.GetPointData()).AddArray(array)
    if cells:
        mapper.SetScalarModeToUseCellFieldData()
    else:
        mapper.SetScalarModeToUsePointFieldData()
    mapper.SelectColorArray(name)
    mapper.SetLookupTable(lookup)
    mapper.UseLookupTableScalarRangeOn()
    return mapper


def points_actor(mapper, size_px, spheres):
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetRepresentationToPoints()
    if spheres:
        actor.GetProperty().RenderPointsAsSpheresOn()
    actor.GetProperty().SetPointSize(size_px)
    return actor


def particle_actor(dataset, lookup, colour_by_speed, radius_px):
    poly = surface(dataset)
    speed = None
    if colour_by_speed:
        speed = np.linalg.norm(vtk_to_numpy(poly.GetPointData().GetArray("velocity")), axis=1)
    actor = points_actor(mapper_for(poly, lookup, speed, "speed"), radius_px, spheres=True)
    if not colour_by_speed:
        actor.GetProperty().SetColor(0.78, 0.70, 0.55)
    return actor


def shell_actor(dataset, lookup, colour_by_stress):
    poly = surface(dataset)
    cells = poly.GetCellData()
    stress = None
    if colour_by_stress and cells.GetArray("von_mises_top") is not None:
        layers = [vtk_to_numpy(cells.GetArray(f"von_mises_{s}"))
                  for s in ("top", "middle", "bottom")]
        stress = np.max(layers, axis=0) / 1e6
    actor = vtkActor()
    actor.SetMapper(mapper_for(poly, lookup, stress, "von_mises_MPa", cells=True))
    if not colour_by_stress:
        actor.GetProperty().SetColor(0.55, 0.60, 0.68)
        actor.GetProperty().SetOpacity(0.12)
    actor.GetProperty().EdgeVisibilityOff()
    return actor


def wall_actor(dataset, radius_px):
    """A rigid wall's particles (a swinging door) as small dark grey points."""
    actor = points_actor(mapper_for(surface(dataset), None), max(1.0, 0.5 * radius_px),
                         spheres=False)
    actor.GetProperty().SetColor(0.25, 0.25, 0.25)
    return actor


def lookup_table(low, high):
    lookup = vtkLookupTable()
    lookup.SetRange(low, high)
    lookup.SetHueRange(0.667, 0.0)  # blue (low) to red (high)
    lookup.Build()
    return lookup


def render(vtm_path, time, args, png_path):
    colour = args.color
    low, high = args.range
    lookup = lookup_table(low, high)
    renderer = vtkRenderer()
    renderer.SetBackground(1.0, 1.0, 1.0)
    for name, block in blocks(vtm_path):
        if block is None or block.GetNumberOfPoints() == 0:
            continue
        if name.startswith("wall_"):
            if name[len("wall_"):] in args.walls:
                shown = mirrored(block, args.mirror) if args.mirror else block
                renderer.AddActor(wall_actor(shown, args.point))
            continue
        is_shell = block.IsA("vtkUnstructuredGrid")  # before mirroring, which makes a grid
        if args.mirror:
            block = mirrored(block, args.mirror)
        if is_shell:
            renderer.AddActor(shell_actor(block, lookup, colour == "von_mises"))
        else:
            renderer.AddActor(particle_actor(block, lookup, colour == "velocity", args.point))
    bar = vtkScalarBarActor()
    bar.SetLookupTable(lookup)
    bar.SetTitle("speed [m/s]" if colour == "velocity" else "von Mises [MPa]")
    bar.GetTitleTextProperty().SetColor(0, 0, 0)
    bar.GetLabelTextProperty().SetColor(0, 0, 0)
    bar.SetNumberOfLabels(5)
    bar.SetWidth(0.08)
    renderer.AddActor2D(bar)
    label = vtkTextActor()
    label.SetInput(f"t = {time:.2f} s")
    label.GetTextProperty().SetColor(0, 0, 0)
    label.GetTextProperty().SetFontSize(28)
    label.SetPosition(20, 20)
    renderer.AddActor2D(label)
    camera = renderer.GetActiveCamera()
    camera.SetViewUp(0.0, 0.0, 1.0)
    camera.SetPosition(1.0, 0.0, 0.0)
    camera.SetFocalPoint(0.0, 0.0, 0.0)
    renderer.ResetCamera()
    camera.Azimuth(args.view[0])
    camera.Elevation(args.view[1])
    renderer.ResetCamera()
    camera.Zoom(args.zoom)
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(*args.size)
    window.AddRenderer(renderer)
    window.Render()
    image = vtkWindowToImageFilter()
    image.SetInput(window)
    image.Update()
    writer = vtkPNGWriter()
    writer.SetFileName(png_path)
    writer.SetInputConnection(image.GetOutputPort())
    writer.Write()


def parse(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("out", help="the run's output directory")
    parser.add_argument("--times", required=True, help="comma-separated times [s]")
    parser.add_argument("--color", choices=("velocity", "von_mises"), default="velocity")
    parser.add_argument("--mirror", default="", help="x, y or x,y: reflect in x = 0, y = 0")
    parser.add_argument("--view", default="-60,25", help="camera azimuth,elevation [deg]")
    parser.add_argument("--zoom", type=float, default=1.3)
    parser.add_argument("--size", default="1600x900")
    parser.add_argument("--point", type=float, default=4.0, help="sphere size [pixels]")
    parser.add_argument("--range", default=None, help="colour range LO,HI")
    parser.add_argument("--prefix", default=None)
    parser.add_argument("--walls", default="", help="wall blocks to draw (rigid walls that move)")
    args = parser.parse_args(argv)
    args.times = [float(t) for t in args.times.split(",")]
    args.mirror = [a for a in args.mirror.split(",") if a]
    if any(a not in ("x", "y") for a in args.mirror):
        parser.error("--mirror takes x, y or x,y")
    args.view = [float(v) for v in args.view.split(",")]
    args.size = [int(v) for v in args.size.lower().split("x")]
    default_range = "0,3" if args.color == "velocity" else "0,200"
    args.range = [float(v) for v in (args.range or default_range).split(",")]
    args.prefix = args.prefix or args.color
    args.walls = [w for w in args.walls.split(",") if w]
    return args


def main(argv):
    args = parse(argv)
    frames = frames_of(args.out)
    os.makedirs(os.path.join(args.out, "pictures"), exist_ok=True)
    for wanted in args.times:
        time, vtm = min(frames, key=lambda frame: abs(frame[0] - wanted))
        png = os.path.join(args.out, "pictures", f"{args.prefix}_t{round(time * 100):04d}.png")
        render(vtm, time, args, png)
        print(f"render_frames: t = {time:g} s -> {png}")


if __name__ == "__main__":
    main(sys.argv[1:])
