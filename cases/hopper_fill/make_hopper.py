#!/usr/bin/env python3
"""Writes hopper.stl (run from this folder): a square pyramid-frustum hopper in mm, outlet
closed, 10 triangles. Top opening 200 x 200 mm at z = 200 mm, bottom 60 x 60 mm at z = 0.
Normals (right-hand rule of the vertex order) point into the hopper, where the sand is,
as grainload's mesh walls expect."""

TOP, BOTTOM, HEIGHT = 100.0, 30.0, 200.0
ring_bottom = [(-BOTTOM, -BOTTOM, 0.0), (BOTTOM, -BOTTOM, 0.0), (BOTTOM, BOTTOM, 0.0),
               (-BOTTOM, BOTTOM, 0.0)]
ring_top = [(-TOP, -TOP, HEIGHT), (TOP, -TOP, HEIGHT), (TOP, TOP, HEIGHT), (-TOP, TOP, HEIGHT)]


def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def inward(t):
    """Order t so that its normal points towards the hopper axis (or up for the bottom)."""
    n = cross(sub(t[1], t[0]), sub(t[2], t[0]))
    centre = [sum(v[k] for v in t) / 3 for k in range(3)]
    towards = (-centre[0], -centre[1], HEIGHT / 2 - centre[2])
    return t if sum(a * b for a, b in zip(n, towards)) > 0 else (t[0], t[2], t[1])


triangles = [inward((ring_bottom[0], ring_bottom[1], ring_bottom[2])),
             inward((ring_bottom[0], ring_bottom[2], ring_bottom[3]))]
for k in range(4):
    b0, b1 = ring_bottom[k], ring_bottom[(k + 1) % 4]
    t0, t1 = ring_top[k], ring_top[(k + 1) % 4]
    triangles += [inward((b0, b1, t1)), inward((b0, t1, t0))]

with open("hopper.stl", "w") as f:
    f.write("solid hopper (mm, normals into the hopper)\n")
    for t in triangles:
        n = cross(sub(t[1], t[0]), sub(t[2], t[0]))
        length = sum(c * c for c in n) ** 0.5
        f.write("  facet normal %.6g %.6g %.6g\n    outer loop\n" % tuple(c / length + 0.0 for c in n))
        for v in t:
            f.write("      vertex %g %g %g\n" % v)
        f.write("    endloop\n  endfacet\n")
    f.write("endsolid hopper\n")
