#!/usr/bin/env python3
"""Pictures of a wall-load map ([[sph.wall_map]], docs/user-guide/sph.md).

  plot_wall_map.py OUT NAME                     window: mean and maximum pressure, mean
                                                traction, and the ring (or row) means
  plot_wall_map.py OUT NAME --instant N         the interval means of file NAME_N.csv
  plot_wall_map.py OUT NAME --history A,B       one cell's interval means against time (A, B:
                                                axial position in m and angle in deg, or u, v)
  --png FILE                                    where the picture goes (default: beside the maps)
"""
import argparse
import glob
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def label(column):
    return column.replace("_Pa", "").replace("_", " ")


def read(path):
    return np.genfromtxt(path, delimiter=",", names=True)


def grid(table, column):
    """The column as a 2D array: rows along the first coordinate, columns along the second."""
    first = np.unique(table[table.dtype.names[2]])
    second = np.unique(table[table.dtype.names[3]])
    return first, second, table[column].reshape(len(first), len(second))


def edges(centres):
    step = centres[1] - centres[0] if len(centres) > 1 else 1.0
    return np.concatenate([centres - step / 2, [centres[-1] + step / 2]])


def draw_map(axes, table, column, title):
    first, second, values = grid(table, column)
    image = axes.pcolormesh(edges(second), edges(first), values / 1e3, shading="flat",
                            cmap="viridis")
    axes.set_xlabel(table.dtype.names[3].replace("_", " "))
    axes.set_ylabel(table.dtype.names[2].replace("_", " "))
    axes.set_title(title)
    plt.colorbar(image, ax=axes, label="kPa")


def ring_means(axes, table, columns):
    first, _, _ = grid(table, columns[0])
    for column in columns:
        _, _, values = grid(table, column)
        axes.plot(values.mean(axis=1) / 1e3, first, marker="o", label=label(column))
    axes.set_xlabel("mean around (kPa)")
    axes.set_ylabel(table.dtype.names[2].replace("_", " "))
    axes.grid(True)
    axes.legend(fontsize="small")


def window_picture(folder, name):
    table = read(os.path.join(folder, name + "_window.csv"))
    shear = [c for c in table.dtype.names if c.startswith("mean_shear")][0]
    figure, axes = plt.subplots(1, 4, figsize=(18, 4.5))
    span = f"{table['window_start_s'][0]:g}-{table['window_end_s'][0]:g} s"
    draw_map(axes[0], table, "mean_pressure_Pa", f"mean pressure, {span}")
    draw_map(axes[1], table, "max_pressure_Pa", f"maximum of interval means, {span}")
    draw_map(axes[2], table, shear, label(shear))
    ring_means(axes[3], table, ["mean_pressure_Pa", "max_pressure_Pa", shear])
    return figure


def instant_picture(folder, name, instant):
    table = read(os.path.join(folder, f"{name}_{instant:06d}.csv"))
    shear = [c for c in table.dtype.names if c.startswith("shear")][0]
    figure, axes = plt.subplots(1, 3, figsize=(14, 4.5))
    when = f"t = {table['time_s'][0]:g} s (mean over {table['interval_s'][0]:g} s)"
    draw_map(axes[0], table, "pressure_Pa", "pressure, " + when)
    draw_map(axes[1], table, shear, label(shear))
    ring_means(axes[2], table, ["pressure_Pa", shear])
    return figure


def history_picture(folder, name, point):
    times, loads = [], []
    for path in sorted(glob.glob(os.path.join(folder, name + "_[0-9]*.csv"))):
        table = read(path)
        a, b = table[table.dtype.names[2]], table[table.dtype.names[3]]
        cell = np.argmin((a - point[0]) ** 2 + (b - point[1]) ** 2)
        times.append(table["time_s"][cell])
        loads.append([table[c][cell] for c in table.dtype.names[4:]])
        columns = table.dtype.names[4:]
    figure, axes = plt.subplots(figsize=(7, 4.5))
    for k, column in enumerate(columns):
        axes.plot(times, np.array(loads)[:, k] / 1e3, marker=".", label=label(column))
    axes.set_xlabel("time (s)")
    axes.set_ylabel("interval mean (kPa)")
    axes.set_title(f"{name}: the cell at {point[0]:g}, {point[1]:g}")
    axes.grid(True)
    axes.legend()
    return figure


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("out", help="the run's output directory")
    parser.add_argument("name", help="the map's name")
    parser.add_argument("--instant", type=int)
    parser.add_argument("--history")
    parser.add_argument("--png")
    args = parser.parse_args()
    folder = os.path.join(args.out, "wall_maps")
    if args.history:
        point = [float(v) for v in args.history.split(",")]
        figure, suffix = history_picture(folder, args.name, point), "history"
    elif args.instant is not None:
        figure, suffix = instant_picture(folder, args.name, args.instant), f"{args.instant:06d}"
    else:
        figure, suffix = window_picture(folder, args.name), "window"
    figure.tight_layout()
    png = args.png or os.path.join(folder, f"{args.name}_{suffix}.png")
    figure.savefig(png, dpi=110)
    print(png)


if __name__ == "__main__":
    main()
