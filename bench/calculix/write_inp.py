#!/usr/bin/env python3
"""Write CalculiX (ccx 2.20) input decks for the peer half of bench/shell_solve.

Two models, both meshed as N x N shell elements (S4, or S8R where asked for):

scordelis  Scordelis-Lo roof, quarter model.
           Reference: MacNeal & Harder, "A proposed standard set of problems to test
           finite element accuracy", Finite Elem. Anal. Des. 1 (1985) 3-20:
           vertical displacement 0.3024 at the middle of the free edge.  That is the
           value MacNeal & Harder recommend for this (shallow-shell-theory) problem;
           0.3086 is the deep-shell-theory value some authors quote.  We compare with
           0.3024, as fem/shell_benchmarks.cpp does.

           Axes (the same as fem/shell_benchmarks.cpp, make_cylinder):
             y  cylinder axis; y = 0 is the rigid end diaphragm, y = L/2 = 25 mid-span;
             z  vertical, up; the crown is the line x = 0, z = R;
             x  horizontal, across the roof; x = R sin(phi), z = R cos(phi),
                phi in [0, 40 deg]; phi = 40 deg is the free longitudinal edge.
           R = 25, t = 0.25, E = 4.32e8, nu = 0, self-weight 90 per unit area in -z.
           Monitor: node (phi = 40 deg, y = 25), displacement u_z (negative; we report
           its magnitude).

plate      Full square plate a x a in the plane z = 0, simply supported on all four
           edges (w = 0), uniform pressure q in -z.
           Reference: Timoshenko & Woinowsky-Krieger, "Theory of Plates and Shells",
           2nd ed. 1959, Table 8: w_max = 0.00406 q a^4 / D (nu = 0.3, b/a = 1),
           D = E t^3 / (12 (1 - nu^2)).  We evaluate the Navier series behind that table
           (0.0040624 q a^4 / D) so the 3-digit rounding does not show up as error.
           Defaults: a = 1, t = 0.01 (a/t = 100, thin enough that transverse shear
           adds only a few 1e-4 to w), E = 2.1e11, nu = 0.3, q = 1000.
           Monitor: the centre node, u_z.

Boundary conditions on expanded shells.  ccx turns every S4 into a C3D8I brick and
every S8R into a C3D20R brick; the shell node becomes a reference node tied by MPCs to
the expanded nodes through the thickness.  A translational *BOUNDARY on a shell node
only fixes the mean of the through-thickness nodes, so the section may still rotate
about the edge: a hinge (16 x 16 S4 then gives 0.408 instead of 0.300).  Symmetry
needs a rotational condition too.  The ccx manual (theory part, "Applying the SPC's
to the expanded structure") says that a rotational SPC on a shell node without a knot
becomes a mean-rotation MPC about the global axis.  The expanded nodes lie on the
shell normal n at +-t/2, so (our reading, which matches every variant we ran) a
rotation about the axis a constrains only their relative displacement along a x n.
Consequences for the two symmetry lines:
  mid-span y = 25, n = (sin phi, 0, cos phi):
    x x n = (0, -cos phi, 0) and z x n = (0, sin phi, 0): theta_x = 0 and theta_z = 0
    each say the same thing, "top and bottom do not move apart in y", which is the
    whole symmetry condition for the section.  Imposing both makes ccx's constraint
    set redundant and the roof comes out about ten times too stiff (0.0308 at
    16 x 16), so we impose u_y and theta_x only: DOF 2, 4.  (theta_x is well posed
    on the whole arc, cos phi >= cos 40 deg.)
  crown x = 0, n = z:
    y x z = x: theta_y = 0 says "top and bottom do not move apart in x".  theta_z is
    a drilling rotation there (z x n = 0) and is left alone: DOF 1, 5.
Rigid diaphragm y = 0: u_x = u_z = 0 (no motion in its own plane), u_y and all
rotations free.  These choices reproduce the figures of earlier CalculiX 2.20 runs
(16 x 16 S4: 0.3005, 64 x 64: 0.3015, 8 x 8 S8R: 0.3020).
For the plate, w = 0 on the mid-surface nodes lets the edge section rotate about the
edge, as a simple support must.  Kirchhoff's support also implies dw/ds = 0 along the
edge, i.e. no rotation about the edge normal; a thick (3D-brick) model without it has
the "soft" support and its boundary layer, which raises the centre deflection by about
0.7 % at a/t = 100 (measured, 200 x 200 S4: 2.128e-4 against 2.112e-4).  So we also fix
theta_x on the edges x = 0, a and theta_y on y = 0, a ("hard" support, DOF 4 / 5; by
the argument above each is the single condition "top and bottom do not move apart
along the edge"); --soft-support (or the model name plate_soft) drops it, for
comparison with a shell model whose edge rotations are all free.  The in-plane
translations of the edge nodes are fixed too; in a linear analysis of a flat plate
they do not couple to w and only remove the rigid in-plane motions.

Usage:
  write_inp.py scordelis N [--element S4|S8R|S4R] [-o FILE]
  write_inp.py plate|plate_soft N [--element S4|S8R] [--a A] [--t T] [--E E] [--nu NU] [--q Q]
                      [--soft-support] [-o FILE]

One line of metadata for run_peer.sh (space separated key=value), on stdout when the
deck goes to a file (-o), on stderr when the deck goes to stdout:
  model= element= n= elements= nodes= monitor_node= monitor_dof= reference= sign=
"""

import argparse
import math
import sys


# --------------------------------------------------------------------------- meshes

class Grid:
    """Structured N x N shell mesh on a parameter square (s, r) in [0,1]^2.

    Nodes live on a (2N+1) x (2N+1) lattice for S8R (corner + mid-side nodes, no centre
    node) and on an (N+1) x (N+1) lattice for S4; ids are assigned only to used lattice
    points so that the node count (and with it ccx's equation count) is honest.
    """

    def __init__(self, n, element):
        self.n = n
        self.element = element
        self.quadratic = element.startswith("S8")
        self.m = 2 * n if self.quadratic else n  # lattice intervals per side
        self.ids = {}
        next_id = 1
        for j in range(self.m + 1):
            for i in range(self.m + 1):
                if self.quadratic and i % 2 == 1 and j % 2 == 1:
                    continue  # element centre: S8R has no node there
                self.ids[(i, j)] = next_id
                next_id += 1

    def node_count(self):
        return len(self.ids)

    def node(self, i, j):
        return self.ids[(i, j)]

    def elements(self):
        """Connectivity in ccx order: corners counter-clockwise in (s, r), then mid-sides."""
        step = 2 if self.quadratic else 1
        eid = 1
        for j in range(0, self.m, step):
            for i in range(0, self.m, step):
                if self.quadratic:
                    c = [(i, j), (i + 2, j), (i + 2, j + 2), (i, j + 2)]
                    mids = [(i + 1, j), (i + 2, j + 1), (i + 1, j + 2), (i, j + 1)]
                    yield eid, [self.node(*p) for p in c + mids]
                else:
                    c = [(i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)]
                    yield eid, [self.node(*p) for p in c]
                eid += 1

    def edge(self, side):
        """Node ids on one side of the parameter square: 's0', 's1', 'r0', 'r1'."""
        out = []
        for (i, j), nid in self.ids.items():
            if ((side == "s0" and i == 0) or (side == "s1" and i == self.m)
                    or (side == "r0" and j == 0) or (side == "r1" and j == self.m)):
                out.append(nid)
        return sorted(out)


def write_id_list(f, ids):
    # ccx accepts up to 16 entries per data line; 10 keeps the lines readable.
    for k in range(0, len(ids), 10):
        f.write(", ".join(str(x) for x in ids[k:k + 10]) + ",\n")


def write_nodes(f, grid, position):
    f.write("*NODE, NSET=NALL\n")
    for (i, j), nid in sorted(grid.ids.items(), key=lambda kv: kv[1]):
        x, y, z = position(i / grid.m, j / grid.m)
        f.write(f"{nid}, {x:.12g}, {y:.12g}, {z:.12g}\n")


def write_elements(f, grid):
    f.write(f"*ELEMENT, TYPE={grid.element}, ELSET=EALL\n")
    count = 0
    for eid, conn in grid.elements():
        f.write(f"{eid}, " + ", ".join(str(c) for c in conn) + "\n")
        count += 1
    return count


# ------------------------------------------------------------------------- models

SL_R = 25.0
SL_HALF_L = 25.0
SL_PHI = math.radians(40.0)
SL_T = 0.25
SL_E = 4.32e8
SL_NU = 0.0
SL_Q = 90.0
SL_REF = 0.3024  # MacNeal & Harder 1985 (0.3086 is the deep-shell value)


def scordelis(f, n, element):
    grid = Grid(n, element)

    # s runs around the arc (phi = 0 at the crown), r along the axis (y = 0 diaphragm).
    def position(s, r):
        phi = s * SL_PHI
        return SL_R * math.sin(phi), r * SL_HALF_L, SL_R * math.cos(phi)

    f.write("** Scordelis-Lo roof, quarter model, written by bench/calculix/write_inp.py\n")
    f.write("** axes: y = cylinder axis (y=0 diaphragm, y=25 mid-span), z up, crown at x=0\n")
    write_nodes(f, grid, position)
    elements = write_elements(f, grid)

    diaphragm, midspan = grid.edge("r0"), grid.edge("r1")
    crown, free = grid.edge("s0"), grid.edge("s1")
    monitor = grid.node(grid.m, grid.m)
    for name, ids in (("DIAPHRAGM", diaphragm), ("MIDSPAN", midspan), ("CROWN", crown),
                      ("MON", [monitor])):
        f.write(f"*NSET, NSET={name}\n")
        write_id_list(f, ids)

    f.write("*MATERIAL, NAME=ROOF\n*ELASTIC\n")
    f.write(f"{SL_E:.6g}, {SL_NU:.6g}\n")
    # Self-weight as gravity: density * t * g = 90 per unit mid-surface area with g = 1.
    # (For a cylinder the brick volume equals mid-surface area times t exactly.)
    f.write("*DENSITY\n")
    f.write(f"{SL_Q / SL_T:.12g}\n")
    f.write(f"*SHELL SECTION, ELSET=EALL, MATERIAL=ROOF\n{SL_T:.12g}\n")

    f.write("*STEP\n*STATIC\n*BOUNDARY\n")
    f.write("DIAPHRAGM, 1, 1\nDIAPHRAGM, 3, 3\n")        # rigid in its own plane (x-z)
    f.write("MIDSPAN, 2, 2\nMIDSPAN, 4, 4\n")  # symmetry, plane y = 25 (see docstring)
    f.write("CROWN, 1, 1\nCROWN, 5, 5\n")   # symmetry, plane x = 0 (see docstring)
    f.write("*DLOAD\nEALL, GRAV, 1., 0., 0., -1.\n")
    f.write("*NODE PRINT, NSET=MON\nU\n")
    f.write("*END STEP\n")
    return dict(model="scordelis_lo", elements=elements, nodes=grid.node_count(),
                monitor_node=monitor, monitor_dof=3, reference=SL_REF, sign=-1)


def navier_plate_coefficient(terms=401):
    """alpha in w_centre = alpha q a^4 / D for a simply supported square plate.

    Navier double sine series (Timoshenko & Woinowsky-Krieger, Navier solution for the
    uniformly loaded simply supported plate, at the centre):
    w = 16 q / (pi^6 D) sum_{m,n odd} (-1)^((m+n)/2-1) / (m n (m^2/a^2+n^2/b^2)^2).
    The series alone does not depend on nu (nu only enters through D).
    """
    total = 0.0
    for m in range(1, terms + 1, 2):
        for k in range(1, terms + 1, 2):
            sign = -1.0 if ((m + k) // 2 - 1) % 2 else 1.0
            total += sign / (m * k * (m * m + k * k) ** 2)
    return 16.0 / math.pi ** 6 * total


def plate(f, n, element, a, t, E, nu, q, hard_support=True):
    grid = Grid(n, element)
    # The centre is a lattice point when N is even (S4) or always (S8R, lattice 2N).
    if grid.m % 2:
        raise SystemExit("plate: N must be even so that a node sits at the centre")

    def position(s, r):
        return s * a, r * a, 0.0

    f.write("** Simply supported square plate under uniform pressure, "
            "written by bench/calculix/write_inp.py\n")
    write_nodes(f, grid, position)
    elements = write_elements(f, grid)
    edges = sorted(set(grid.edge("s0") + grid.edge("s1") + grid.edge("r0") + grid.edge("r1")))
    monitor = grid.node(grid.m // 2, grid.m // 2)
    f.write("*NSET, NSET=EDGES\n")
    write_id_list(f, edges)
    # Edges x = 0, a (normal x) and y = 0, a (normal y), for the twist condition below.
    f.write("*NSET, NSET=EDGES_X\n")
    write_id_list(f, sorted(set(grid.edge("s0") + grid.edge("s1"))))
    f.write("*NSET, NSET=EDGES_Y\n")
    write_id_list(f, sorted(set(grid.edge("r0") + grid.edge("r1"))))
    f.write("*NSET, NSET=MON\n")
    write_id_list(f, [monitor])

    f.write("*MATERIAL, NAME=PLATE\n*ELASTIC\n")
    f.write(f"{E:.12g}, {nu:.12g}\n")
    f.write(f"*SHELL SECTION, ELSET=EALL, MATERIAL=PLATE\n{t:.12g}\n")
    f.write("*STEP\n*STATIC\n*BOUNDARY\n")
    f.write("EDGES, 1, 3\n")  # w = 0 (+ in-plane, decoupled in linear analysis)
    if hard_support:
        # Kirchhoff's support also has dw/ds = 0 along the edge, i.e. no rotation
        # about the edge normal ("hard" support).  Without it the section may twist
        # at the edge and the thick-shell bricks develop the soft-support boundary
        # layer, which here raises w by about 0.7 % at a/t = 100.
        f.write("EDGES_X, 4, 4\nEDGES_Y, 5, 5\n")
    # Nodes run counter-clockwise seen from +z, so the shell normal is +z, and ccx
    # pushes a positive P along that normal here (checked: P > 0 lifts the plate).
    # Write -q so that the load acts downward like the roof's gravity.
    f.write(f"*DLOAD\nEALL, P, {-q:.12g}\n")
    f.write("*NODE PRINT, NSET=MON\nU\n")
    f.write("*END STEP\n")

    D = E * t ** 3 / (12.0 * (1.0 - nu * nu))
    reference = navier_plate_coefficient() * q * a ** 4 / D
    return dict(model="plate_ss" if hard_support else "plate_ss_soft", elements=elements,
                nodes=grid.node_count(),
                monitor_node=monitor, monitor_dof=3, reference=reference, sign=-1)


def main(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("model", choices=["scordelis", "plate", "plate_soft"])
    p.add_argument("n", type=int, help="elements per side")
    p.add_argument("--element", default="S4", choices=["S4", "S4R", "S8R"])
    p.add_argument("-o", "--output", help="deck to write (default: stdout)")
    p.add_argument("--a", type=float, default=1.0, help="plate: side length")
    p.add_argument("--t", type=float, default=0.01, help="plate: thickness")
    p.add_argument("--E", type=float, default=2.1e11, help="plate: Young's modulus")
    p.add_argument("--nu", type=float, default=0.3, help="plate: Poisson's ratio")
    p.add_argument("--q", type=float, default=1000.0, help="plate: pressure (downward)")
    p.add_argument("--soft-support", action="store_true",
                   help="plate: leave the twist at the edges free (default: hard support)")
    args = p.parse_args(argv)
    if args.n < 1:
        p.error("N must be positive")

    out = open(args.output, "w") if args.output else sys.stdout
    try:
        if args.model == "scordelis":
            meta = scordelis(out, args.n, args.element)
        else:
            meta = plate(out, args.n, args.element, args.a, args.t, args.E, args.nu, args.q,
                         hard_support=not args.soft_support and args.model != "plate_soft")
    finally:
        if args.output:
            out.close()
    meta.update(element=args.element, n=args.n)
    keys = ("model", "element", "n", "elements", "nodes", "monitor_node", "monitor_dof",
            "reference", "sign")
    line = " ".join(f"{k}={meta[k]:.8g}" if k == "reference" else f"{k}={meta[k]}"
                    for k in keys)
    # Metadata goes to stderr when the deck itself goes to stdout.
    print(line, file=sys.stderr if not args.output else sys.stdout)


if __name__ == "__main__":
    main(sys.argv[1:])
