#!/usr/bin/env python3
"""Side views (distance from the column's axis vs height) of column-collapse frames, for
docs/validation/column_collapse.md. Reads the body block of grainload's .vtp frames (appended,
zlib-compressed) with numpy alone. Usage:
  plot_profiles.py OUT.png LABEL=FRAME.vtp [LABEL=FRAME.vtp ...]   (/usr/bin/python3)"""
import re
import struct
import sys
import zlib

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def read_points(path):
    """The Points array of a VTK XML PolyData file with raw appended, zlib-compressed data
    (header_type UInt32: block count, block size, last block size, compressed sizes)."""
    raw = open(path, "rb").read()
    head, data = raw.split(b'<AppendedData encoding="raw">', 1)
    data = data[data.index(b"_") + 1:]
    offset = int(re.search(r'<Points>\s*<DataArray[^>]*offset="(\d+)"',
                           head.decode("latin1")).group(1))
    blocks = struct.unpack("<I", data[offset:offset + 4])[0]
    sizes = struct.unpack(f"<{blocks}I", data[offset + 12:offset + 12 + 4 * blocks])
    position, out = offset + 12 + 4 * blocks, b""
    for size in sizes:
        out += zlib.decompress(data[position:position + size])
        position += size
    return np.frombuffer(out, dtype="<f8").reshape(-1, 3)


runs = [argument.split("=", 1) for argument in sys.argv[2:]]
figure, axes = plt.subplots(1, len(runs), figsize=(2.6 * len(runs), 3.2), sharey=True)
for axis, (label, path) in zip(np.atleast_1d(axes), runs):
    x = read_points(path)
    axis.scatter(np.hypot(x[:, 0], x[:, 1]) * 1e3, x[:, 2] * 1e3, s=4)
    axis.set_title(label, fontsize=8)
    axis.set_xlabel("r (mm)")
    axis.set_xlim(-5, 150)
    axis.set_ylim(0, 215)
    axis.set_aspect("equal")
np.atleast_1d(axes)[0].set_ylabel("z (mm)")
figure.tight_layout()
figure.savefig(sys.argv[1], dpi=110)
