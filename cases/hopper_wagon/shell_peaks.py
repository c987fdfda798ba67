#!/usr/bin/env python3
"""Peak displacement and von Mises stress of each shell block of a grainload frame, and where:
python3 shell_peaks.py FRAME.vtm [--away X Y Z R ...]

For wagon_pressure.toml: out/wagon_pressure/frames/wagon_pressure_000001.vtm (the last frame).
Per block (one per [[fem.shell]] part): the node of the largest |displacement| and the element
of the largest von Mises stress (the largest of von_mises_top, _middle, _bottom), with their
undeformed positions; --away X Y Z R (m, repeatable) also gives the peak stress of the elements
whose centre is farther than R from the point (X, Y, Z), e.g. away from a stress concentration.
Reads grainload's VTK XML files (appended raw data, zlib-compressed, UInt32 headers: io/ writes
them so). Standard library only.
"""
import argparse
import math
import os
import re
import struct
import zlib

FORMATS = {"Float64": "d", "Float32": "f", "Int64": "q", "Int32": "i", "UInt8": "B"}


def read_vtu(path):
    """{array name: list of tuples} of a .vtu with appended raw zlib data."""
    with open(path, "rb") as f:
        raw = f.read()
    appended = raw.index(b"<AppendedData")
    head = raw[:appended].decode()
    start = raw.index(b"_", raw.index(b">", appended)) + 1
    arrays = {}
    for tag in re.findall(r"<DataArray\s[^>]*>", head):
        name = re.search(r'Name="([^"]+)"', tag).group(1)
        kind = FORMATS[re.search(r'type="([^"]+)"', tag).group(1)]
        components = re.search(r'NumberOfComponents="(\d+)"', tag)
        components = int(components.group(1)) if components else 1
        position = start + int(re.search(r'offset="\s*(\d+)', tag).group(1))
        blocks = struct.unpack_from("<I", raw, position)[0]
        sizes = struct.unpack_from(f"<{blocks}I", raw, position + 12)
        position += 12 + 4 * blocks
        data = b""
        for size in sizes:
            data += zlib.decompress(raw[position:position + size])
            position += size
        values = struct.unpack(f"<{len(data) // struct.calcsize(kind)}{kind}", data)
        arrays[name] = [values[i:i + components] for i in range(0, len(values), components)]
    return arrays


def block_peaks(arrays, away):
    points, u = arrays["Points"], arrays["displacement"]
    origin = [tuple(p - d for p, d in zip(x, v)) for x, v in zip(points, u)]
    node = max(range(len(u)), key=lambda n: math.hypot(*u[n]))
    connectivity = [c[0] for c in arrays["connectivity"]]
    ends = [o[0] for o in arrays["offsets"]]
    stress = [max(t[0], m[0], b[0]) for t, m, b in zip(
        arrays["von_mises_top"], arrays["von_mises_middle"], arrays["von_mises_bottom"])]
    centres = []
    for e, end in enumerate(ends):
        cell = connectivity[(ends[e - 1] if e else 0):end]
        centres.append(tuple(sum(origin[n][d] for n in cell) / len(cell) for d in range(3)))
    def peak(elements):
        e = max(elements, key=lambda k: stress[k])
        return f"{stress[e] / 1e6:.1f} MPa at {fmt(centres[e])} (thickness " \
               f"{arrays['thickness'][e][0] * 1e3:.0f} mm)"
    lines = [f"peak |u| {math.hypot(*u[node]) * 1e3:.2f} mm at {fmt(origin[node])}, "
             f"u = ({', '.join(f'{v * 1e3:.2f}' for v in u[node])}) mm",
             f"peak von Mises {peak(range(len(stress)))}"]
    if away:
        far = [e for e in range(len(stress))
               if all(math.dist(centres[e], a[:3]) > a[3] for a in away)]
        lines.append(f"peak von Mises away from the given points {peak(far)}")
    return lines


def fmt(x):
    return "(" + ", ".join(f"{v:.3f}" for v in x) + ") m"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("frame")
    parser.add_argument("--away", nargs=4, type=float, action="append", default=[],
                        metavar=("X", "Y", "Z", "R"))
    args = parser.parse_args()
    with open(args.frame) as f:
        files = re.findall(r'file="([^"]+\.vtu)"', f.read())
    for name in files:
        arrays = read_vtu(os.path.join(os.path.dirname(args.frame), name))
        print(f"{os.path.basename(name)}: " + "; ".join(block_peaks(arrays, args.away)))


if __name__ == "__main__":
    main()
