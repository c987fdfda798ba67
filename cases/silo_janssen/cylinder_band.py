"""Writes cylinder_band.stl: a band of the silo's wall, the cylinder of radius 0.15 m from
z = 0 to z = 0.1 m as 48 facets around and 2 up (each a quad cut in two triangles), ASCII STL,
normals pointing in. The DEM silo stacks it with `offset` into the wall's bands, and its CI
version shrinks it with `scale`. Usage: python3 cases/silo_janssen/cylinder_band.py"""
import math
import os

RADIUS, HEIGHT, AROUND, UP = 0.15, 0.1, 48, 2


def main():
    def vertex(i, j):
        angle = 2.0 * math.pi * (i % AROUND) / AROUND
        return (RADIUS * math.cos(angle), RADIUS * math.sin(angle), HEIGHT * j / UP)

    lines = ["solid cylinder_band"]
    for j in range(UP):
        for i in range(AROUND):
            a, b, c, d = vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1), vertex(i, j + 1)
            # a-d-c and a-c-b wind clockwise seen from outside: the normal points in.
            for tri in ((a, d, c), (a, c, b)):
                lines.append("facet normal 0 0 0")
                lines.append("outer loop")
                lines += ["vertex %.9f %.9f %.9f" % v for v in tri]
                lines.append("endloop")
                lines.append("endfacet")
    lines.append("endsolid cylinder_band")
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "cylinder_band.stl")
    with open(path, "w") as out:
        out.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
