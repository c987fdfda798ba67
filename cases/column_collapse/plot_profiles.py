#!/usr/bin/env python3
"""Side views (distance from the column's axis vs height) of column-collapse frames, for
docs/validation/column_collapse.md. Each frame is a run's .vtm (its body block is drawn) or one
body's .vtp. Usage (ParaView's or Debian's python3-vtk9, with matplotlib):
  /usr/bin/python3 plot_profiles.py OUT.png LABEL=FRAME [LABEL=FRAME ...]"""
import sys

import matplotlib
import numpy as np

from compare_frames import body_positions

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    runs = [argument.split("=", 1) for argument in sys.argv[2:]]
    figure, axes = plt.subplots(1, len(runs), figsize=(2.6 * len(runs), 3.2), sharey=True)
    for axis, (label, path) in zip(np.atleast_1d(axes), runs):
        x = body_positions(path)
        axis.scatter(np.hypot(x[:, 0], x[:, 1]) * 1e3, x[:, 2] * 1e3, s=4)
        axis.set_title(label, fontsize=8)
        axis.set_xlabel("r (mm)")
        axis.set_xlim(-5, 150)
        axis.set_ylim(0, 215)
        axis.set_aspect("equal")
    np.atleast_1d(axes)[0].set_ylabel("z (mm)")
    figure.tight_layout()
    figure.savefig(sys.argv[1], dpi=110)


if __name__ == "__main__":
    main()
