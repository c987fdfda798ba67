#!/usr/bin/env python3
"""Writes the lifting tube of the repose cases as an STL surface (run from this folder):
an open-ended circular cylinder (no bottom, no top), the axis along z through the origin,
made of `segments` flat panels. Vertex order gives normals pointing into the tube, where the
sand is, as grainload's mesh walls expect (the wall's particle layers are built outside).

    python3 make_tube.py     # tube.stl, for repose.toml and its variants at other angles
    python3 make_tube.py --radius 132 --height 230 --segments 32 --out tube_small.stl  # CI

Lengths in mm."""
import argparse
import math


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--radius", type=float, default=96.0, help="tube radius, mm")
    parser.add_argument("--height", type=float, default=180.0, help="tube height, mm")
    parser.add_argument("--segments", type=int, default=48, help="panels around the tube")
    parser.add_argument("--out", default="tube.stl")
    args = parser.parse_args()

    ring = [(args.radius * math.cos(2 * math.pi * k / args.segments),
             args.radius * math.sin(2 * math.pi * k / args.segments))
            for k in range(args.segments)]
    # Rows of panels about as tall as they are wide: grainload samples a triangle on a grid
    # set by its longest edge, so long thin triangles would get far more wall particles than
    # the wall spacing asks for.
    width = 2 * args.radius * math.sin(math.pi / args.segments)
    rows = max(1, round(args.height / width))
    triangles = []
    for row in range(rows):
        z0, z1 = args.height * row / rows, args.height * (row + 1) / rows
        for k in range(args.segments):
            (x0, y0), (x1, y1) = ring[k], ring[(k + 1) % args.segments]
            b0, b1 = (x0, y0, z0), (x1, y1, z0)
            t0, t1 = (x0, y0, z1), (x1, y1, z1)
            # Walking b0 -> t0 -> t1 (anticlockwise seen from inside) puts (t0 - b0) x
            # (t1 - b0) towards the axis.
            triangles += [(b0, t0, t1), (b0, t1, b1)]

    with open(args.out, "w") as f:
        f.write("solid tube (mm, normals into the tube)\n")
        for a, b, c in triangles:
            u = [b[i] - a[i] for i in range(3)]
            v = [c[i] - a[i] for i in range(3)]
            n = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
            centre = [(a[i] + b[i] + c[i]) / 3 for i in range(2)]
            assert n[0] * centre[0] + n[1] * centre[1] < 0, "normal must point to the axis"
            length = math.sqrt(sum(x * x for x in n))
            f.write("  facet normal %.6g %.6g %.6g\n    outer loop\n"
                    % tuple(x / length + 0.0 for x in n))
            for p in (a, b, c):
                f.write("      vertex %.6g %.6g %.6g\n" % p)
            f.write("    endloop\n  endfacet\n")
        f.write("endsolid tube\n")


if __name__ == "__main__":
    main()
