#!/usr/bin/env python3
"""Writes the mesh fixtures of this folder (run from it: python3 make_meshes.py).

cube_ascii.stl / cube_binary.stl: the cube [-0.25, 0.75] x [-0.5, 0.5] x [0, 1] m, 12
triangles, normals outward (STL convention); every coordinate is exact in float32, so both
files hold the same numbers. cube_open.stl: the same without its two top triangles.
degenerate.stl: the cube with one triangle collapsed onto a line. square_quads.msh: the
square [0, 1] x [0, 1] at z = 0 as 2 x 2 quadrangles, normal +z. cube_quads.msh: the cube
[0, 1]^3 as 6 quadrangles, normals outward. polyline.msh: a V of two lines in z = 0 from
(0, 1) down to (1, 0) and up to (2, 1), material above (left of the walking direction).
"""
import struct

LO = (-0.25, -0.5, 0.0)
HI = (0.75, 0.5, 1.0)


def corner(i, j, k):
    return (HI[0] if i else LO[0], HI[1] if j else LO[1], HI[2] if k else LO[2])


# Faces as corner index triples (i, j, k), counter-clockwise seen from outside.
QUADS = [
    [(0, 0, 0), (0, 1, 0), (1, 1, 0), (1, 0, 0)],  # z = lo, normal -z
    [(0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)],  # z = hi, normal +z
    [(0, 0, 0), (1, 0, 0), (1, 0, 1), (0, 0, 1)],  # y = lo, normal -y
    [(0, 1, 0), (0, 1, 1), (1, 1, 1), (1, 1, 0)],  # y = hi, normal +y
    [(0, 0, 0), (0, 0, 1), (0, 1, 1), (0, 1, 0)],  # x = lo, normal -x
    [(1, 0, 0), (1, 1, 0), (1, 1, 1), (1, 0, 1)],  # x = hi, normal +x
]


def cube_triangles():
    tris = []
    for q in QUADS:
        c = [corner(*v) for v in q]
        tris.append((c[0], c[1], c[2]))
        tris.append((c[0], c[2], c[3]))
    return tris


def write_ascii(name, tris):
    with open(name, "w") as f:
        f.write("solid cube\n")
        for t in tris:
            f.write("  facet normal 0 0 0\n    outer loop\n")
            for v in t:
                f.write("      vertex %r %r %r\n" % v)
            f.write("    endloop\n  endfacet\n")
        f.write("endsolid cube\n")


def write_binary(name, tris):
    with open(name, "wb") as f:
        f.write(b"solid cube (binary; the size decides)".ljust(80, b" "))
        f.write(struct.pack("<I", len(tris)))
        for t in tris:
            f.write(struct.pack("<3f", 0.0, 0.0, 0.0))
            for v in t:
                f.write(struct.pack("<3f", *v))
            f.write(struct.pack("<H", 0))


def write_msh(name, nodes, blocks):
    """blocks: list of (entity_dim, element_type, [node tag lists])."""
    with open(name, "w") as f:
        f.write("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n")
        f.write("$Nodes\n1 %d 1 %d\n2 1 0 %d\n" % (len(nodes), len(nodes), len(nodes)))
        for k in range(len(nodes)):
            f.write("%d\n" % (k + 1))
        for x in nodes:
            f.write("%r %r %r\n" % x)
        f.write("$EndNodes\n$Elements\n")
        total = sum(len(b[2]) for b in blocks)
        f.write("%d %d 1 %d\n" % (len(blocks), total, total))
        tag = 1
        for dim, etype, elements in blocks:
            f.write("%d 1 %d %d\n" % (dim, etype, len(elements)))
            for e in elements:
                f.write("%d %s\n" % (tag, " ".join(str(n) for n in e)))
                tag += 1
        f.write("$EndElements\n")


tris = cube_triangles()
write_ascii("cube_ascii.stl", tris)
write_binary("cube_binary.stl", tris)
write_ascii("cube_open.stl", [t for t in tris if not all(v[2] == HI[2] for v in t)])
bad = list(tris)
bad[3] = (bad[3][0], bad[3][0], bad[3][2])
write_ascii("degenerate.stl", bad)

grid = [(0.5 * i, 0.5 * j, 0.0) for j in range(3) for i in range(3)]
quads = [[1 + i + 3 * j, 2 + i + 3 * j, 5 + i + 3 * j, 4 + i + 3 * j]
         for j in range(2) for i in range(2)]
write_msh("square_quads.msh", grid, [(0, 15, [[1]]), (2, 3, quads)])

unit = [(float(i), float(j), float(k)) for k in range(2) for j in range(2) for i in range(2)]


def tag(i, j, k):
    return 1 + i + 2 * j + 4 * k


write_msh("cube_quads.msh", unit, [(2, 3, [[tag(*v) for v in q] for q in QUADS])])
write_msh("polyline.msh", [(0.0, 1.0, 0.0), (1.0, 0.0, 0.0), (2.0, 1.0, 0.0)],
          [(0, 15, [[2]]), (1, 1, [[1, 2], [2, 3]])])
