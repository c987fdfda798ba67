"""Read the point arrays of a grainload particle frame (.vtp, VTK XML, raw appended data,
zlib compressed, UInt32 headers) without VTK's Python module: numpy and zlib only."""
import re
import struct
import zlib

import numpy as np


def read_vtp(path):
    """{name: array (n, components)} for every DataArray, "points" for the positions."""
    data = open(path, "rb").read()
    start = data.index(b"<AppendedData")
    blob = data[data.index(b"_", start) + 1:]
    head = data[:start].decode("latin-1")
    n = int(re.search(r'NumberOfPoints="(\d+)"', head).group(1))
    arrays = {}
    for tag in re.finditer(r"<DataArray ([^>]*)>", head):
        attrs = dict(re.findall(r'(\w+)="([^"]*)"', tag.group(1)))
        if "offset" not in attrs:
            continue
        name = attrs.get("Name", "points")
        comps = int(attrs.get("NumberOfComponents", "1"))
        off = int(attrs["offset"])
        blocks = struct.unpack_from("<I", blob, off)[0]
        sizes = struct.unpack_from("<%dI" % (3 + blocks), blob, off)[3:]
        pos = off + 4 * (3 + blocks)
        raw = b""
        for size in sizes:
            raw += zlib.decompress(blob[pos:pos + size])
            pos += size
        dtype = {"Float64": "<f8", "Float32": "<f4", "Int32": "<i4", "Int64": "<i8",
                 "UInt8": "u1"}[attrs["type"]]
        values = np.frombuffer(raw, dtype=dtype)
        if n > 0 and values.size % n == 0 and values.size >= n:
            values = values.reshape(n, -1)
        arrays[name] = values
    return arrays
