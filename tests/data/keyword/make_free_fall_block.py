#!/usr/bin/env python3
"""Writes free_fall_block.k (run from this folder): the 4 x 4 x 8 particles of
cases/free_fall/free_fall_small.toml's box body (cell centres of [0, 100] x [0, 100] x
[1000, 1200] mm on a 25 mm lattice) as *ELEMENT_SPH particles of part 1 "block", in mm-t-s,
each of mass 2099 kg/m^3 * (25 mm)^3 = 3.2796875e-5 t, the way a pre-processor would write
them: *NODE in fixed format, the particles on one card with NID..NEND generation."""
SPACING = 25.0
MASS = 2099.0 * (SPACING * 1e-3) ** 3 / 1000.0  # t
lines = ["*KEYWORD", "$ the free_fall_small block as LS-DYNA SPH particles (mm-t-s)", "*NODE"]
nid = 0
for k in range(8):
    for j in range(4):
        for i in range(4):
            nid += 1
            x = ((i + 0.5) * SPACING, (j + 0.5) * SPACING, 1000.0 + (k + 0.5) * SPACING)
            lines.append(f"{nid:8d}" + "".join(f"{v:16.4f}" for v in x))
lines += ["*PART", "block", f"{1:10d}", "*ELEMENT_SPH", f"{1:8d}{1:8d}{MASS:16.9e}{nid:8d}",
          "*END"]
with open("free_fall_block.k", "w") as f:
    f.write("\n".join(lines) + "\n")
