#!/usr/bin/python3
"""Render grainload frames to PNG off screen with VTK's Python bindings (python3-vtk9).

    scripts/render_frames.py OUT --times 0,2.5,11 [--color velocity|von_mises]
                             [--mirror x,y] [--walls door|none] [--view AZIMUTH,ELEVATION]
                             [--up x|y|z] [--zoom 1.0] [--size 1600x900] [--point 4]
                             [--range LO,HI] [--title TEXT] [--no-axes] [--prefix NAME]

OUT is a run's output directory (its .pvd lists the frames and their times); every time picks
the frame nearest to it. Particle blocks are drawn as spheres coloured by speed |v| (m/s);
shell blocks as surfaces coloured by the von Mises stress, the largest of the top, middle
and bottom surfaces (MPa). Wall particles (the `wall_*` point sets) are drawn as small light
grey points in a scene without shells (the walls of a slot silo); in a scene with shells they
are left out, as most of them sample a shell, which is drawn instead. `--walls door` draws the
named walls dark grey in any scene (a door that swings open); `--walls none` leaves them all
out. `--color von_mises` greys the particles so the shell stands out. `--mirror x,y` reflects
everything in the planes x = 0 and y = 0, so a quarter model is shown whole. The pictures go
to OUT/pictures/PREFIX_tNNN.png (time in centiseconds).

Every picture carries a title (the case's name, or --title), the time stamp, axes in metres
along the scene's bounds and a colour bar with the quantity, its unit, round ticks and the
largest value in the frame. The colour range runs from 0 to a round number at or above the
largest value of all the frames asked for (the same scale for the series); `--range LO,HI`
fixes it instead, and values above HI are then drawn in the above-range colour, which the bar
shows. The camera looks at the scene from the horizontal direction of azimuth 0 with the
vertical up: the axis against gravity in the case file (`--up` sets it), then turns by
AZIMUTH about the vertical and ELEVATION above the horizontal (a plane strain case: 0, 0), and
is panned and zoomed so that the scene's bounding box fills the picture but for the room its
labels need; `--zoom` scales that fit. A stress picture rings the place of the largest stress
and writes its value beside it.

Without a display (CI, ssh) run it under xvfb-run (package xvfb): `xvfb-run -a python3 ...`.
"""

import argparse
import json
import os
import re
import sys

import vtkmodules.vtkRenderingFreeType  # noqa: F401  (text)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (registers the OpenGL render window)
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkLookupTable
from vtkmodules.vtkFiltersGeneral import vtkReflectionFilter
from vtkmodules.vtkFiltersGeometry import vtkGeometryFilter
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import (
    vtkActor,
    vtkPolyDataMapper,
    vtkRenderer,
    vtkRenderWindow,
    vtkWindowToImageFilter,
)
import numpy as np

import frame_annotations as notes
from vtk_frames import blocks, frames_of

CAPTIONS = {"velocity": "particle speed\n(m/s)",
            "von_mises": "von Mises stress\n(MPa), shell faces"}
# Camera position (from the focal point) and the two horizontal axes for each vertical axis.
VIEW_FRAMES = {"z": ((1.0, 0.0, 0.0), (0.0, 0.0, 1.0)), "y": ((0.0, 0.0, 1.0), (0.0, 1.0, 0.0)),
               "x": ((0.0, 1.0, 0.0), (1.0, 0.0, 0.0))}


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


def speeds(dataset):
    return np.linalg.norm(vtk_to_numpy(dataset.GetPointData().GetArray("velocity")), axis=1)


def stresses_mpa(dataset):
    """Per cell the largest von Mises stress of the shell's three surfaces, MPa (None for a
    shell without them)."""
    cells = dataset.GetCellData()
    if cells.GetArray("von_mises_top") is None:
        return None
    layers = [vtk_to_numpy(cells.GetArray(f"von_mises_{s}")) for s in ("top", "middle", "bottom")]
    return np.max(layers, axis=0) / 1e6


def is_wall_sample(name, block):
    """A rigid wall's or a coupled shell's wall particles: a point set named wall_*."""
    return name.startswith("wall_") and not block.IsA("vtkUnstructuredGrid")


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
    speed = speeds(poly) if colour_by_speed else None
    actor = points_actor(mapper_for(poly, lookup, speed, "speed"), radius_px, spheres=True)
    if not colour_by_speed:
        actor.GetProperty().SetColor(0.78, 0.70, 0.55)
    return actor


def shell_actor(dataset, lookup, colour_by_stress):
    poly = surface(dataset)
    stress = stresses_mpa(poly) if colour_by_stress else None
    actor = vtkActor()
    actor.SetMapper(mapper_for(poly, lookup, stress, "von_mises_MPa", cells=True))
    if stress is None:
        actor.GetProperty().SetColor(0.55, 0.60, 0.68)
        actor.GetProperty().SetOpacity(0.12)
    actor.GetProperty().EdgeVisibilityOff()
    return actor


def wall_actor(dataset, radius_px, highlighted):
    """A rigid wall's particles as small points: light grey, or dark grey when highlighted (a
    swinging door)."""
    actor = points_actor(mapper_for(surface(dataset), None), max(1.0, 0.5 * radius_px),
                         spheres=False)
    actor.GetProperty().SetColor(*((0.25,) * 3 if highlighted else (0.72,) * 3))
    return actor


def lookup_table(low, high):
    lookup = vtkLookupTable()
    lookup.SetRange(low, high)
    lookup.SetHueRange(0.667, 0.0)  # blue (low) to red (high)
    lookup.SetAboveRangeColor(*notes.ABOVE_RANGE, 1.0)
    lookup.UseAboveRangeColorOn()
    lookup.Build()
    return lookup


def largest_value(vtm_path, colour):
    """The largest speed of the particles (m/s) or von Mises stress of the shells (MPa) in
    the frame, and where it is (a point, m; None when nothing carries the quantity)."""
    largest, where = 0.0, None
    for name, block in blocks(vtm_path):
        if block is None or block.GetNumberOfPoints() == 0 or is_wall_sample(name, block):
            continue
        shell = block.IsA("vtkUnstructuredGrid")
        if colour == "velocity" and not shell:
            values = speeds(block)
            k = int(np.argmax(values))
            if values[k] > largest:
                largest, where = float(values[k]), block.GetPoint(k)
        elif colour == "von_mises" and shell:
            values = stresses_mpa(block)
            if values is not None and values.size and np.max(values) > largest:
                k = int(np.argmax(values))
                bounds = block.GetCell(k).GetBounds()
                largest = float(values[k])
                where = tuple((bounds[2 * i] + bounds[2 * i + 1]) / 2 for i in range(3))
    return largest, where


def nearest_image(point, planes, eye):
    """Of the point and its mirror images (--mirror), the one nearest the camera."""
    images = [np.array(point, dtype=float)]
    for axis in planes:
        k = "xyz".index(axis)
        for image in list(images):
            flipped = image.copy()
            flipped[k] = -flipped[k]
            images.append(flipped)
    return min(images, key=lambda p: float(np.linalg.norm(p - np.array(eye))))


def scene_actors(vtm_path, args, lookup):
    """The frame's actors: particles, shells and rigid walls (mirrored)."""
    actors = []
    named = blocks(vtm_path)
    shells = any(block is not None and block.IsA("vtkUnstructuredGrid") for _, block in named)
    for name, block in named:
        if block is None or block.GetNumberOfPoints() == 0:
            continue
        if is_wall_sample(name, block):
            wall = name[len("wall_"):]
            if wall in args.walls or (not shells and "none" not in args.walls):
                shown = mirrored(block, args.mirror) if args.mirror else block
                actors.append(wall_actor(shown, args.point, wall in args.walls))
            continue
        is_shell = block.IsA("vtkUnstructuredGrid")  # before mirroring, which makes a grid
        if args.mirror:
            block = mirrored(block, args.mirror)
        if is_shell:
            actors.append(shell_actor(block, lookup, args.color == "von_mises"))
        else:
            actors.append(particle_actor(block, lookup, args.color == "velocity", args.point))
    return actors


def place_camera(renderer, args):
    camera = renderer.GetActiveCamera()
    position, up = VIEW_FRAMES[args.up]
    camera.SetViewUp(*up)
    camera.SetPosition(*position)
    camera.SetFocalPoint(0.0, 0.0, 0.0)
    renderer.ResetCamera()
    camera.Azimuth(args.view[0])
    camera.Elevation(args.view[1])
    camera.OrthogonalizeViewUp()
    renderer.ResetCamera()


def fit_camera(scene, bounds, layout, zoom):
    """Pans and zooms the camera so that the scene's bounding box, projected, fills the scene's
    part of the picture less the room its axes' labels need (about five characters beside it
    and two and a half lines under it: frame_annotations.metre_axes), then zooms by `zoom`."""
    f = layout.font
    left, right = 4.5 * f, layout.width - layout.bar_column - 1.5 * f
    bottom, top = layout.bottom_strip + 2.5 * f, layout.height - layout.top_strip
    corners = [(bounds[i], bounds[2 + j], bounds[4 + k]) for i in (0, 1) for j in (0, 1)
               for k in (0, 1)]
    camera = scene.GetActiveCamera()
    for _ in range(12):
        points = [notes.display_point(scene, c) for c in corners]
        xs, ys = [p[0] for p in points], [p[1] for p in points]
        scale = min((right - left) / max(max(xs) - min(xs), 1.0),
                    (top - bottom) / max(max(ys) - min(ys), 1.0))
        shift = ((left + right - min(xs) - max(xs)) / 2, (bottom + top - min(ys) - max(ys)) / 2)
        if abs(scale - 1.0) < 0.01 and max(abs(shift[0]), abs(shift[1])) < 1.0:
            break
        # Pan: move the camera and its focal point by the world shift at the focal plane.
        focal = camera.GetFocalPoint()
        scene.SetWorldPoint(*focal, 1.0)
        scene.WorldToDisplay()
        fx, fy, depth = scene.GetDisplayPoint()
        scene.SetDisplayPoint(fx - shift[0], fy - shift[1], depth)
        scene.DisplayToWorld()
        moved = scene.GetWorldPoint()
        step = [moved[k] / moved[3] - focal[k] for k in range(3)]
        camera.SetFocalPoint(*[focal[k] + step[k] for k in range(3)])
        camera.SetPosition(*[camera.GetPosition()[k] + step[k] for k in range(3)])
        camera.Zoom(scale)
    camera.Zoom(zoom)
    scene.ResetCameraClippingRange()


def render(vtm_path, time, args, scale, png_path):
    """One frame to png_path. `scale` is (low, high, tick step, the series' largest value)."""
    low, high, step, _ = scale
    largest, where = largest_value(vtm_path, args.color)
    caption = notes.bar_caption(CAPTIONS[args.color], largest, step)
    layout = notes.Layout(*args.size, caption)
    lookup = lookup_table(low, high)
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(*args.size)
    window.SetNumberOfLayers(2)
    paper = vtkRenderer()  # the white ground of the strips around the scene
    paper.SetBackground(1.0, 1.0, 1.0)
    scene = vtkRenderer()
    scene.SetBackground(1.0, 1.0, 1.0)
    scene.SetViewport(*layout.scene_viewport())
    annotations = vtkRenderer()  # a layer over the whole window for the text and the bar
    annotations.SetLayer(1)
    for renderer in (paper, scene, annotations):
        window.AddRenderer(renderer)
    for actor in scene_actors(vtm_path, args, lookup):
        scene.AddActor(actor)
    bounds = scene.ComputeVisiblePropBounds()
    place_camera(scene, args)
    fit_camera(scene, bounds, layout, args.zoom)
    overlay = (notes.title_actors(layout, args.title, f"t = {time:.2f} s")
               + notes.colour_bar(layout, lookup, low, high, step, caption,
                                  above=scale[3] > high * (1.0 + 1e-9)))
    taken = []  # pixel boxes of the labels placed over the scene
    if args.axes:
        overlay += notes.metre_axes(scene, bounds, layout, args.up, taken)
    if args.color == "von_mises" and where is not None:
        where = nearest_image(where, args.mirror, scene.GetActiveCamera().GetPosition())
        overlay += notes.peak_marker(scene, where, f"{largest:.3g} MPa", layout, taken)
    for actor in overlay:
        annotations.AddActor2D(actor)
    window.Render()
    image = vtkWindowToImageFilter()
    image.SetInput(window)
    image.Update()
    writer = vtkPNGWriter()
    writer.SetFileName(png_path)
    writer.SetInputConnection(image.GetOutputPort())
    writer.Write()
    return largest


def case_facts(out):
    """The case's name, its vertical axis (against gravity) and whether it is plane strain,
    from the run's summary.json and case file, where they can be read."""
    try:
        with open(os.path.join(out, "summary.json")) as f:
            summary = json.load(f)
    except (OSError, ValueError):
        return None, None, False
    flat = summary.get("model", {}).get("dimension") == "plane strain"
    up = None
    case_file = summary.get("case_file", "")
    for path in (case_file, os.path.join(out, "..", case_file)):
        if os.path.isfile(path):
            found = re.search(r'^\s*gravity\s*=\s*"([^"]*)"', open(path).read(), re.MULTILINE)
            if found:
                g = [float(v) for v in re.findall(r"[-+]?[0-9.]+(?:[eE][-+]?[0-9]+)?",
                                                  found.group(1).split("m/")[0])][:3]
                up = "xyz"[int(np.argmax(np.abs(g)))] if any(g) else None
            break
    return summary.get("case"), up, flat


def parse(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("out", help="the run's output directory")
    parser.add_argument("--times", required=True, help="comma-separated times [s]")
    parser.add_argument("--color", choices=("velocity", "von_mises"), default="velocity")
    parser.add_argument("--mirror", default="", help="x, y or x,y: reflect in x = 0, y = 0")
    parser.add_argument("--view", help="camera azimuth,elevation [deg] (default -60,25; a plane "
                        "strain case: 0,0, square on)")
    parser.add_argument("--up", choices=("x", "y", "z"), help="the vertical axis")
    parser.add_argument("--zoom", type=float, default=1.0,
                        help="the scene larger (>1) or smaller than the fit to the picture")
    parser.add_argument("--size", default="1600x900")
    parser.add_argument("--point", type=float, default=4.0, help="sphere size [pixels]")
    parser.add_argument("--range", default=None, help="colour range LO,HI (default: the data's)")
    parser.add_argument("--title", help="the picture's title (default: the case's name)")
    parser.add_argument("--no-axes", dest="axes", action="store_false", help="no axes in m")
    parser.add_argument("--prefix", default=None)
    parser.add_argument("--walls", default="", help="rigid walls to draw dark grey (a door), "
                        "or none")
    args = parser.parse_args(argv)
    args.times = [float(t) for t in args.times.split(",")]
    args.mirror = [a for a in args.mirror.split(",") if a]
    if any(a not in ("x", "y") for a in args.mirror):
        parser.error("--mirror takes x, y or x,y")
    args.size = [int(v) for v in args.size.lower().split("x")]
    if args.range:
        args.range = [float(v) for v in args.range.split(",")]
        if len(args.range) != 2 or not args.range[1] > args.range[0]:
            parser.error("--range takes LO,HI with HI > LO")
    args.prefix = args.prefix or args.color
    args.walls = [w for w in args.walls.split(",") if w]
    return args


def main(argv):
    args = parse(argv)
    frames = frames_of(args.out)
    case, up, flat = case_facts(args.out)
    args.up = args.up or up or "z"
    args.view = [float(v) for v in (args.view or ("0,0" if flat else "-60,25")).split(",")]
    pvd_name = [n for n in os.listdir(args.out) if n.endswith(".pvd")][0][:-4]
    args.title = args.title or case or pvd_name
    chosen = [min(frames, key=lambda frame: abs(frame[0] - wanted)) for wanted in args.times]
    largest = max(largest_value(vtm, args.color)[0] for _, vtm in chosen)
    if args.range:
        low, high = args.range
        step = None
    else:
        low, (high, step) = 0.0, notes.round_top(largest)
    unit = "m/s" if args.color == "velocity" else "MPa"
    os.makedirs(os.path.join(args.out, "pictures"), exist_ok=True)
    for time, vtm in chosen:
        png = os.path.join(args.out, "pictures", f"{args.prefix}_t{round(time * 100):04d}.png")
        own = render(vtm, time, args, (low, high, step, largest), png)
        print(f"render_frames: t = {time:g} s -> {png} (colour range {low:g} to {high:g} {unit}, "
              f"largest {own:.6g} {unit})")


if __name__ == "__main__":
    main(sys.argv[1:])
