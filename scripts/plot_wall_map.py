#!/usr/bin/python3
"""Pictures of a wall-load map ([[sph.wall_map]] or [[dem.wall_map]], docs/user-guide/sph.md).

  plot_wall_map.py OUT NAME                     window: mean and maximum pressure, mean
                                                traction, and the ring (or row) means
  plot_wall_map.py OUT NAME --instant N         the interval means of file NAME_N.csv
  plot_wall_map.py OUT NAME --history A,B       one cell's interval means against time (A, B:
                                                axial position in m and angle in deg, or u, v)
  --png FILE                                    where the picture goes (default: beside the maps)
  --radius R                                    a cylinder's radius in m (default: the case
                                                file's, read through the run's summary.json)

Lengths are in metres and loads in kPa. A cylinder is drawn unrolled: the axial position
against the arc length R theta around the wall (the angle in degrees on the top axis). A plane
map is drawn on its own u, v grid and says so. A map one cell wide (a plane-strain wall, or
bins = [n, 1]) is drawn as profiles along its cells, the mean and the maximum beside each
other, not as a strip of invented width. The mean and the maximum maps share one colour scale.
"""
import argparse
import glob
import json
import os
import re

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

UNITS = {"m": 1.0, "cm": 1e-2, "mm": 1e-3}


def read(path):
    return np.genfromtxt(path, delimiter=",", names=True)


class Grid:
    """The map's cells: the first coordinate (axial or u) by the second (angle or v), in m."""

    def __init__(self, table, radius):
        names = table.dtype.names
        self.cylinder = "axial_m" in names
        first_name, second_name = ("axial_m", "angle_deg") if self.cylinder else ("u_m", "v_m")
        self.first = np.unique(table[first_name])
        self.second_raw = np.unique(table[second_name])
        self.radius = radius
        self.second = (np.radians(self.second_raw) * radius if self.cylinder and radius
                       else self.second_raw)
        self.one_wide = len(self.second) == 1

    def values(self, table, column):
        return table[column].reshape(len(self.first), len(self.second)) / 1e3  # kPa

    def first_label(self):
        return "axial position (m)" if self.cylinder else "u, along edge_u (m)"

    def second_label(self):
        if not self.cylinder:
            return "v, along edge_v (m)"
        return "around the wall, R θ (m)" if self.radius else "angle around the axis (deg)"

    def kind(self):
        if self.cylinder:
            return (f"unrolled cylinder, R = {self.radius:g} m" if self.radius
                    else "unrolled cylinder")
        return "plane map, plane strain (per m of depth)" if self.one_wide else "plane map"


def edges(centres, width):
    return np.concatenate([centres - width / 2, [centres[-1] + width / 2]])


def cell_width(centres):
    return centres[1] - centres[0] if len(centres) > 1 else 1.0


def case_radius(out, name):
    """The map's radius in m from the case file that summary.json names, or None."""
    try:
        with open(os.path.join(out, "summary.json")) as f:
            case_file = json.load(f)["case_file"]
        text = open(case_file).read()
    except (OSError, ValueError, KeyError):
        return None
    for block in re.split(r"\[\[(?:sph|dem)\.wall_map\]\]", text)[1:]:
        block = block.split("\n[")[0]
        if re.search(r'^\s*name\s*=\s*"' + re.escape(name) + '"', block, re.MULTILINE):
            found = re.search(r'^\s*radius\s*=\s*"([-+0-9.eE]+)\s*(m|cm|mm)"', block, re.MULTILINE)
            return float(found.group(1)) * UNITS[found.group(2)] if found else None
    return None


def interval_length(folder, name):
    """The output interval the maps' interval means are taken over, s (None if unknown)."""
    files = sorted(glob.glob(os.path.join(folder, name + "_[0-9]*.csv")))
    return float(read(files[-1])["interval_s"].flat[0]) if files else None


def draw_map(figure, axes, grid, values, title, scale, cmap="viridis"):
    second_width = cell_width(grid.second)
    image = axes.pcolormesh(edges(grid.second, second_width),
                            edges(grid.first, cell_width(grid.first)), values, shading="flat",
                            cmap=cmap, vmin=scale[0], vmax=scale[1])
    axes.set_xlabel(grid.second_label())
    axes.set_ylabel(grid.first_label())
    axes.set_title(title)
    if grid.cylinder and grid.radius:
        top = axes.secondary_xaxis(
            "top", functions=(lambda s: np.degrees(s / grid.radius),
                              lambda a: np.radians(a) * grid.radius))
        top.set_xlabel("angle (deg)")
    figure.colorbar(image, ax=axes, label=title.split(",")[0] + " (kPa)")


def pressure_scale(*maps):
    high = max(float(np.max(m)) for m in maps)
    return 0.0, high if high > 0 else 1.0


def traction_scale(values):
    reach = float(np.max(np.abs(values))) or 1.0
    return -reach, reach


def profiles(axes, grid, curves, xlabel):
    """Profiles along the first coordinate: (values, label, style) each; a mean is a solid line
    with filled circles, a maximum a dashed line with open squares drawn over it."""
    for values, label, style in curves:
        mean = values.mean(axis=1)
        if style == "max":
            axes.plot(mean, grid.first, "s--", markerfacecolor="none", markersize=7,
                      label=label, zorder=3)
        elif style == "traction":
            axes.plot(mean, grid.first, "^:", label=label)
        else:
            axes.plot(mean, grid.first, "o-", label=label)
    axes.set_xlabel(xlabel)
    axes.set_ylabel(grid.first_label())
    axes.grid(True, alpha=0.4)
    axes.legend(fontsize="small")


def traction_name(column):
    direction = column.split("shear_")[1].replace("_Pa", "")
    return {"axial": "axial traction", "circumferential": "circumferential traction",
            "u": "traction along u", "v": "traction along v"}[direction]


def window_picture(folder, name, radius):
    table = read(os.path.join(folder, name + "_window.csv"))
    grid = Grid(table, radius)
    shear = [c for c in table.dtype.names if c.startswith("mean_shear")][0]
    mean, peak = grid.values(table, "mean_pressure_Pa"), grid.values(table, "max_pressure_Pa")
    traction = grid.values(table, shear)
    interval = interval_length(folder, name)
    peak_name = (f"maximum of the {interval:g} s means" if interval
                 else "maximum of the interval means")
    span = f"{table['window_start_s'].flat[0]:g}–{table['window_end_s'].flat[0]:g} s"
    if grid.one_wide:
        figure, axes = plt.subplots(1, 2, figsize=(10, 5), layout="constrained")
        profiles(axes[0], grid, [(mean, "mean pressure", "mean"), (peak, peak_name, "max")],
                 "wall pressure (kPa)")
        profiles(axes[1], grid, [(traction, "mean " + traction_name(shear), "traction")],
                 "wall traction (kPa)")
    else:
        figure, axes = plt.subplots(2, 2, figsize=(11, 9), layout="constrained")
        axes = axes.flat
        scale = pressure_scale(mean, peak)
        draw_map(figure, axes[0], grid, mean, "mean pressure", scale)
        draw_map(figure, axes[1], grid, peak, f"pressure, {peak_name}", scale)
        draw_map(figure, axes[2], grid, traction, "mean " + traction_name(shear),
                 traction_scale(traction), cmap="RdBu_r")
        profiles(axes[3], grid, [(mean, "mean pressure", "mean"), (peak, peak_name, "max"),
                                 (traction, "mean " + traction_name(shear), "traction")],
                 "mean around the wall (kPa)" if grid.cylinder else "mean along v (kPa)")
    figure.suptitle(f"wall map '{name}': {grid.kind()}; window {span}")
    return figure


def instant_picture(folder, name, instant, radius):
    table = read(os.path.join(folder, f"{name}_{instant:06d}.csv"))
    grid = Grid(table, radius)
    shear = [c for c in table.dtype.names if c.startswith("shear")][0]
    pressure, traction = grid.values(table, "pressure_Pa"), grid.values(table, shear)
    when = (f"t = {table['time_s'].flat[0]:g} s, mean over the "
            f"{table['interval_s'].flat[0]:g} s before")
    if grid.one_wide:
        figure, axes = plt.subplots(1, 1, figsize=(6, 5), layout="constrained")
        profiles(axes, grid, [(pressure, "pressure", "mean"),
                              (traction, traction_name(shear), "traction")], "wall load (kPa)")
    else:
        figure, axes = plt.subplots(1, 3, figsize=(15, 5), layout="constrained")
        draw_map(figure, axes[0], grid, pressure, "pressure", pressure_scale(pressure))
        draw_map(figure, axes[1], grid, traction, traction_name(shear),
                 traction_scale(traction), cmap="RdBu_r")
        profiles(axes[2], grid, [(pressure, "pressure", "mean"),
                                 (traction, traction_name(shear), "traction")],
                 "mean around the wall (kPa)" if grid.cylinder else "mean along v (kPa)")
    figure.suptitle(f"wall map '{name}': {grid.kind()}; {when}")
    return figure


def history_picture(folder, name, point):
    times, loads, columns, where = [], [], [], ""
    for path in sorted(glob.glob(os.path.join(folder, name + "_[0-9]*.csv"))):
        table = read(path)
        a, b = table[table.dtype.names[2]], table[table.dtype.names[3]]
        cell = np.argmin((a - point[0]) ** 2 + (b - point[1]) ** 2)
        times.append(table["time_s"][cell])
        loads.append([table[c][cell] for c in table.dtype.names[4:]])
        columns = table.dtype.names[4:]
        where = (f"axial {a[cell]:g} m, angle {b[cell]:g} deg" if "axial_m" in table.dtype.names
                 else f"u = {a[cell]:g} m, v = {b[cell]:g} m")
    figure, axes = plt.subplots(figsize=(7, 4.5), layout="constrained")
    for k, column in enumerate(columns):
        values = np.array(loads)[:, k] / 1e3
        if column != "pressure_Pa" and not np.any(values):
            continue  # a traction that no load has (along v in plane strain)
        label = "pressure" if column == "pressure_Pa" else traction_name(column)
        axes.plot(times, values, marker=".", label=label)
    axes.set_xlabel("time (s)")
    axes.set_ylabel("interval mean (kPa)")
    axes.set_title(f"wall map '{name}': the cell at {where}")
    axes.grid(True, alpha=0.4)
    axes.legend()
    return figure


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("out", help="the run's output directory")
    parser.add_argument("name", help="the map's name")
    parser.add_argument("--instant", type=int)
    parser.add_argument("--history")
    parser.add_argument("--radius", type=float, help="a cylinder's radius (m)")
    parser.add_argument("--png")
    args = parser.parse_args()
    folder = os.path.join(args.out, "wall_maps")
    radius = args.radius or case_radius(args.out, args.name)
    if args.history:
        point = [float(v) for v in args.history.split(",")]
        figure, suffix = history_picture(folder, args.name, point), "history"
    elif args.instant is not None:
        figure = instant_picture(folder, args.name, args.instant, radius)
        suffix = f"{args.instant:06d}"
    else:
        figure, suffix = window_picture(folder, args.name, radius), "window"
    png = args.png or os.path.join(folder, f"{args.name}_{suffix}.png")
    figure.savefig(png, dpi=100)
    print(png)


if __name__ == "__main__":
    main()
