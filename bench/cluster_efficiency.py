#!/usr/bin/env python3
"""Share of useful lanes in a cluster-pair list (docs/performance.md, "Vector lanes").

A cluster-pair scheme (as GROMACS' nbnxm) computes every particle of an i-cluster against every
particle of each j-cluster whose bounding box lies within the list radius of its own. On the
cubic lattice of the 3D granular bench (cubic spline, h = 1.3 dx: support 2.6 dx, Verlet skin
0.13 dx) this prints, per cluster shape, the fraction of those lane pairs that are pairs inside
the support, and the lane pairs per particle, all j-clusters counted (a scheme that takes each
pair once halves both counts, not the fraction).

usage: bench/cluster_efficiency.py
"""

import itertools

import numpy as np

SUPPORT = 2.6  # 2h in lattice spacings
SKIN = 0.13  # 0.1 h


def efficiency(shape):
    """(useful fraction, lane pairs per particle) for clusters of `shape` lattice points."""
    points = np.array(list(itertools.product(*(range(n) for n in shape))), float)
    low, high = points.min(0), points.max(0)
    lanes = useful = 0
    reach = range(-6, 7)
    for offset in itertools.product(reach, reach, reach):
        other = points + np.array(offset, float) * np.array(shape, float)
        gap = np.maximum(0.0, np.maximum(other.min(0) - high, low - other.max(0)))
        if np.sqrt((gap**2).sum()) >= SUPPORT + SKIN:
            continue
        lanes += len(points) * len(other)
        r = np.linalg.norm(points[:, None, :] - other[None, :, :], axis=2)
        useful += int(((r < SUPPORT) & (r > 0.0)).sum())
    return useful / lanes, lanes / len(points)


def main():
    print("# cluster  lanes  useful share  lane pairs per particle")
    for shape in [(1, 1, 1), (4, 1, 1), (2, 2, 1), (2, 2, 2), (4, 2, 1), (8, 1, 1)]:
        share, per_particle = efficiency(shape)
        name = "x".join(str(n) for n in shape)
        print(f"{name:>8} {np.prod(shape):6d} {share:13.3f} {per_particle:24.0f}")


if __name__ == "__main__":
    main()
