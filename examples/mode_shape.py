"""A mode shape to a figure: the default bridge's lowest modes (as `tbridge modes` computes
them, about the verified design's loaded state with the deck's mass), the first drawn over
the bridge at rest.

    PYTHONPATH=build/python python3 examples/mode_shape.py [OUT.png]
"""

import os
import sys

import matplotlib

matplotlib.use("Agg")  # files only: no display needed
import matplotlib.pyplot as plt
import numpy as np

import tbridge

HERE = os.path.dirname(os.path.abspath(__file__))
CONFIG = os.path.join(HERE, "..", "configs", "default.json")


def main(out_png):
    design = tbridge.design(CONFIG)
    modes = tbridge.modes(design, count=3)
    for k, (f, w) in enumerate(zip(modes.frequency_hz, modes.omega_rad_s)):
        print(f"mode {k + 1}: {f:.4f} Hz ({w:.3f} rad/s)")
    nodes = design.nodes
    shape = modes.shapes[0]  # nodes x 3, mass-normalised [m / sqrt(kg)]
    # Drawn at a tenth of the span for the largest node displacement.
    span = np.ptp(nodes[:, 0])
    scaled = nodes + shape * (0.1 * span / np.abs(shape).max())
    fig, ax = plt.subplots(figsize=(7, 3))
    for (i, j), k in zip(design.member_ends, range(len(design.member_names))):
        bar = k < design.num_bars
        ax.plot(nodes[[i, j], 0], nodes[[i, j], 1], color="0.8", lw=2.5 if bar else 0.8)
        ax.plot(scaled[[i, j], 0], scaled[[i, j], 1], color="C3" if bar else "C0", lw=2.5 if bar else 0.8)
    ax.set_aspect("equal")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    ax.set_title(f"mode 1: {modes.frequency_hz[0]:.3f} Hz (grey: at rest)")
    fig.tight_layout()
    fig.savefig(out_png, dpi=120)
    print("wrote", out_png)


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "mode_shape.png")
