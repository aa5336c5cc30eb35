"""A study the sweep section does not know: the verified structure mass of the default bridge
against its deck width, plotted with matplotlib. Each point is `tbridge design` of the config
with one key changed; the verdict of each design is printed beside its mass.

    PYTHONPATH=build/python python3 examples/deck_width_study.py [OUT.png]
"""

import json
import os
import sys

import matplotlib

matplotlib.use("Agg")  # files only: no display needed
import matplotlib.pyplot as plt

import tbridge

HERE = os.path.dirname(os.path.abspath(__file__))
CONFIG = os.path.join(HERE, "..", "configs", "default.json")
WIDTHS_M = [1.0, 1.5, 2.0]


def main(out_png):
    with open(CONFIG) as f:
        config = json.load(f)
    config["bridge"]["n"] = 2  # a smaller bridge than the default: a few seconds a design
    structure_kg, deck_kg = [], []
    for width in WIDTHS_M:
        config["bridge"]["deck_width"] = width
        design = tbridge.design(config)
        total = json.loads(design.to_json())["mass"]
        structure_kg.append(design.structure_mass)
        deck_kg.append(total["deck_beams"])
        print(f"deck width {width:.2f} m: structure {design.structure_mass:.1f} kg, "
              f"deck beams {total['deck_beams']:.1f} kg, {design.verdict}")
    fig, ax = plt.subplots(figsize=(5, 3.5))
    ax.plot(WIDTHS_M, structure_kg, "o-", label="structure (bars and strings)")
    ax.plot(WIDTHS_M, deck_kg, "s--", label="deck beams")
    ax.set_xlabel("deck width [m]")
    ax.set_ylabel("verified mass [kg]")
    ax.set_title("default bridge at n = 2")
    ax.grid(True, alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(out_png, dpi=120)
    print("wrote", out_png)


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "deck_width_study.png")
