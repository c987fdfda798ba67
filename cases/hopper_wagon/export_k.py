#!/usr/bin/env python3
"""Exports the meshed wagon body to an LS-DYNA keyword deck, as FEMAP or LS-PrePost users
would bring it: python3 export_k.py [--case wagon_gravity.toml] [--output hopper_wagon.k]
[--units mm-t-s].

Reads the case file's [[fem.shell]] (generator = "gmsh"): its mesh `file` (made from `geo` by
gmsh first when missing or older, as grainload does) and its [[fem.shell.group]] thicknesses.
Writes, in fixed format and the chosen units: *NODE (ids = Gmsh node tags), one
*SECTION_SHELL_TITLE and *PART per physical surface (title = group name, its thickness),
*ELEMENT_SHELL (ids = Gmsh element tags; a triangle repeats N3), *SET_NODE_LIST_TITLE per
physical curve (its nodes), and a *MAT_ELASTIC for steel, which grainload lists as not read.
Standard library only (tomllib: Python 3.11).
"""
import argparse
import os
import subprocess
import sys
import tomllib

# Deck units: SI value of the length unit, and of the mass unit (stress unit follows).
UNITS = {"mm-t-s": (1e-3, 1e3), "m-kg-s": (1.0, 1.0)}
LENGTH_UNITS = {"m": 1.0, "cm": 1e-2, "mm": 1e-3}


def parse_length(text):
    """'5 mm' -> 0.005 (m)."""
    number, unit = text.split()
    return float(number) * LENGTH_UNITS[unit]


def shell_table(case):
    shells = case["fem"]["shell"]
    if len(shells) != 1 or shells[0].get("generator") != "gmsh":
        sys.exit("export_k.py: expected one [[fem.shell]] with generator = \"gmsh\"")
    return shells[0]


def ensure_mesh(geo, msh):
    """Runs gmsh as io/gmsh_runner.cpp does when the mesh is missing or older."""
    if os.path.exists(msh) and os.path.getmtime(msh) >= os.path.getmtime(geo):
        return
    temporary = f"{msh}.tmp{os.getpid()}.msh"
    subprocess.run(["gmsh", geo, "-2", "-format", "msh41", "-o", temporary], check=True,
                   stdout=subprocess.DEVNULL)
    os.replace(temporary, msh)


def read_msh(path):
    """Nodes {tag: (x, y, z)} in file order, elements [(tag, dim, entity, nodes)], entity
    physical tags {(dim, entity): [tags]} and physical names {(dim, tag): name} of an ASCII
    Gmsh 4.1 file."""
    with open(path) as f:
        lines = iter(f.read().split("\n"))
    nodes, elements, groups, names = {}, [], {}, {}
    for line in lines:
        if line == "$PhysicalNames":
            for _ in range(int(next(lines))):
                dim, tag, name = next(lines).split(maxsplit=2)
                names[(int(dim), int(tag))] = name.strip('"')
        elif line == "$Entities":
            counts = [int(v) for v in next(lines).split()]
            for dim, count in enumerate(counts):
                for _ in range(count):
                    words = next(lines).split()
                    skip = 4 if dim == 0 else 7  # tag + point or bounding box
                    n = int(words[skip])
                    groups[(dim, int(words[0]))] = [int(v) for v in words[skip + 1:skip + 1 + n]]
        elif line == "$Nodes":
            blocks = int(next(lines).split()[0])
            for _ in range(blocks):
                count = int(next(lines).split()[3])
                tags = [int(next(lines)) for _ in range(count)]
                for tag in tags:
                    nodes[tag] = tuple(float(v) for v in next(lines).split()[:3])
        elif line == "$Elements":
            blocks = int(next(lines).split()[0])
            for _ in range(blocks):
                dim, entity, kind, count = (int(v) for v in next(lines).split())
                for _ in range(count):
                    words = [int(v) for v in next(lines).split()]
                    elements.append((words[0], dim, entity, words[1:]))
    return nodes, elements, groups, names


def fields(width, values):
    return "".join(str(v).rjust(width) for v in values)


def write_deck(out, mesh, thickness, units):
    nodes, elements, groups, names = mesh
    length, _ = UNITS[units]
    surfaces = sorted(name for (dim, _), name in names.items() if dim == 2)
    part_of_group = {name: k + 1 for k, name in enumerate(surfaces)}
    out.write(f"*KEYWORD\n*TITLE\nhopper wagon quarter body ({units})\n")
    out.write("*MAT_ELASTIC\n$#     mid        ro         e        pr\n")
    density, young = 7850.0, 210e9
    mass = UNITS[units][1]
    out.write(fields(10, [1, f"{density * length**3 / mass:.4g}",
                          f"{young * length / mass:.6g}", 0.3]) + "\n")
    out.write("*NODE\n$#   nid               x               y               z\n")
    for tag, x in nodes.items():
        out.write(f"{tag:8d}" + "".join(f"{v / length:16.9e}" for v in x) + "\n")
    for name in surfaces:
        pid = part_of_group[name]
        t = thickness[name] / length
        out.write(f"*SECTION_SHELL_TITLE\n{name}\n")
        out.write("$#   secid    elform      shrf       nip\n")
        out.write(fields(10, [pid, 16, "1.0", 2]) + "\n")
        out.write("$#      t1        t2        t3        t4\n")
        out.write(fields(10, [f"{t:.6g}"] * 4) + "\n")
        out.write(f"*PART\n{name}\n" + fields(10, [pid, pid, 1]) + "\n")
    out.write("*ELEMENT_SHELL\n$#   eid     pid      n1      n2      n3      n4\n")
    for tag, dim, entity, element_nodes in elements:
        if dim != 2:
            continue
        named = [names[(2, g)] for g in groups.get((2, entity), []) if (2, g) in names]
        if len(named) != 1:
            sys.exit(f"export_k.py: surface {entity} must be in exactly one physical surface")
        n = element_nodes + [element_nodes[-1]] * (4 - len(element_nodes))
        out.write(fields(8, [tag, part_of_group[named[0]]] + n) + "\n")
    for (dim, tag), name in sorted(names.items()):
        if dim == 2:
            continue
        members = sorted({n for _, d, entity, element_nodes in elements
                          if d == dim and tag in groups.get((d, entity), [])
                          for n in element_nodes})
        out.write(f"*SET_NODE_LIST_TITLE\n{name}\n" + fields(10, [tag]) + "\n")
        for k in range(0, len(members), 8):
            out.write(fields(10, members[k:k + 8]) + "\n")
    out.write("*END\n")


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--case", default=os.path.join(here, "wagon_gravity.toml"))
    parser.add_argument("--output", help="default: hopper_wagon.k beside the case file")
    parser.add_argument("--units", default="mm-t-s", choices=sorted(UNITS))
    args = parser.parse_args()
    with open(args.case, "rb") as f:
        shell = shell_table(tomllib.load(f))
    folder = os.path.dirname(os.path.abspath(args.case))
    msh = os.path.join(folder, shell["file"])
    if "geo" in shell:
        ensure_mesh(os.path.join(folder, shell["geo"]), msh)
    thickness = {g["name"]: parse_length(g["thickness"]) for g in shell["group"]}
    output = args.output or os.path.join(folder, "hopper_wagon.k")
    temporary = output + ".tmp"
    with open(temporary, "w") as out:
        write_deck(out, read_msh(msh), thickness, args.units)
    os.replace(temporary, output)
    print(f"export_k.py: wrote {output}")


if __name__ == "__main__":
    main()
