#!/usr/bin/python3
"""Diagnostic variant: write a copy of a column_collapse_2d case file with a "rough" floor.

This build's wall contact is the frictionless contact potential, so a smooth floor cannot
hold the heap (see docs/validation/column_collapse_2d.md). As a stop-gap until Coulomb wall
friction exists, this script adds a row of single wall particles ("bumps") 1 dp above the floor
plane, one every 3 dp, and raises the column by 1 dp so it starts just touching them. The
bumps give geometric (interlocking) resistance to sliding, not a controlled friction
coefficient. Kernel gradient correction is switched off by default: with it the small case
blew up at t = 0.188 s (density <= 0 at a flow-front particle, see the report).

Usage:
    /usr/bin/python3 cases/column_collapse_2d/rough_floor.py SRC.toml DST.toml SPACING_MM NAME [--kgc]
e.g.
    /usr/bin/python3 cases/column_collapse_2d/rough_floor.py \
        cases/column_collapse_2d/column_collapse_2d.toml /tmp/rough4.toml 4 rough4
"""
import re
import sys

if len(sys.argv) < 5:
    sys.exit(__doc__)
src, dst, dp, name = sys.argv[1], sys.argv[2], float(sys.argv[3]), sys.argv[4]
kgc = "true" if "--kgc" in sys.argv[5:] else "false"
s = open(src).read()
width = 100.0 if "_a1" in src else 200.0  # column width in mm (a = 1 file is 0.1 m wide)
s = re.sub(r'^name = "column_collapse_2d[^"]*"', f'name = "{name}"', s, flags=re.M)
s = re.sub(r'spacing = "[0-9.]+ mm"', f'spacing = "{dp:g} mm"', s)
s = re.sub(r'^min = .*$', f'min = "{1.6 * dp:g} {2.6 * dp:g} mm"', s, flags=re.M)
s = re.sub(r'^max = .*$', f'max = "{1.6 * dp + width:g} {2.6 * dp + 100:g} mm"', s, flags=re.M)
s = s.replace("kernel_gradient_correction = true", f"kernel_gradient_correction = {kgc}")
k, x = 0, 0.5 * dp
while x < 800.0:
    s += (f'\n[[sph.wall]]\nname = "bump{k:03d}"\ntype = "plane"\norigin = "{x:g} {dp:g} mm"\n'
          f'edge_u = "0.01 0 mm"\nnormal = "0 1"\nlayers = 1\n')
    k, x = k + 1, x + 3.0 * dp
with open(dst, "w") as out:
    out.write(s)
