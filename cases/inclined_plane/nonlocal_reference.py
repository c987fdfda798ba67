#!/usr/bin/python3
"""The non-local fluidity's own steady profile on the inclined plane (cases/inclined_plane).

Usage:
    /usr/bin/python3 cases/inclined_plane/nonlocal_reference.py [--grain-size MM]
        [--amplitude A] [--cells N]

Steady uniform flow down a plane at theta: the stress ratio is tan(theta) at every depth, the
pressure p = rho g cos(theta) (H - y). The fluidity of Kamrin & Koval (2012) and Henann & Kamrin
(2013) then obeys, across the layer,
    xi^2 g'' = g - g_loc(y),   xi = A d / sqrt(tan theta - mu_s),
    g_loc = I sqrt(p / rho_s) / (d tan theta),   I = I0 (tan theta - mu_s) / (mu_2 - tan theta),
with zero flux (g' = 0) at the base and at the free surface, the conditions grainload's particle
sums give. Solved by second-order finite differences on N cells (the boundary rows by
reflection); the shear rate is g tan(theta) and u(y) its integral from the sticking base. The
zero-flux conditions keep the integral of g equal to that of g_loc: the surface speed is
Bagnold's, the profile below it is redistributed. Printed: the speeds at fractions of H beside
Bagnold's (the local law). The parameters are those of cases/inclined_plane/bagnold_*.toml.
"""

import argparse
import math

import numpy as np

THETA = math.radians(25.0)
G = 9.81
RHO, RHO_S = 1470.0, 2450.0
MU_S, MU_2, I0 = math.tan(math.radians(20.9)), math.tan(math.radians(32.76)), 0.279
H = 0.02


def profiles(grain_size, amplitude, cells):
    """Heights, the non-local speeds and the local (Bagnold) speeds, m and m/s."""
    mu = math.tan(THETA)
    inertial = I0 * (mu - MU_S) / (MU_2 - mu)
    xi = amplitude * grain_size / math.sqrt(mu - MU_S)
    y = np.linspace(0.0, H, cells + 1)
    step = y[1] - y[0]
    pressure = RHO * G * math.cos(THETA) * (H - y)
    local = inertial * np.sqrt(pressure / RHO_S) / grain_size / mu
    k = (xi / step) ** 2
    matrix = np.diag(np.full(cells + 1, 1.0 + 2.0 * k))
    for i in range(cells + 1):
        for j in (i - 1, i + 1):
            mirrored = 1 if j < 0 else (cells - 1 if j > cells else j)  # g' = 0 by reflection
            matrix[i, mirrored] -= k
    fluidity = np.linalg.solve(matrix, local)

    def integral(rate):
        return np.concatenate([[0.0], np.cumsum(0.5 * (rate[1:] + rate[:-1]) * step)])

    return y, integral(fluidity * mu), integral(local * mu), xi


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--grain-size", type=float, default=2.0, help="d, mm")
    parser.add_argument("--amplitude", type=float, default=0.5, help="A")
    parser.add_argument("--cells", type=int, default=800)
    args = parser.parse_args()
    y, nonlocal_u, local_u, xi = profiles(args.grain_size * 1e-3, args.amplitude, args.cells)
    print(f"d = {args.grain_size} mm, A = {args.amplitude}: xi = {xi * 1e3:.3f} mm, "
          f"{args.cells} cells")
    print("   y/H   non-local u m/s   Bagnold u m/s   ratio")
    for fraction in (0.25, 0.5, 0.75, 0.95, 1.0):
        i = round(fraction * args.cells)
        print(f"  {fraction:5.2f}   {nonlocal_u[i]:15.4f}   {local_u[i]:13.4f}   "
              f"{nonlocal_u[i] / local_u[i]:.3f}")


if __name__ == "__main__":
    main()
