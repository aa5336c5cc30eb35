#!/usr/bin/python3
"""Draws a bridge topology from the design JSON written by `tbridge design CONFIG -o OUT.json`.

Planar bridges are drawn in the x-y plane; the 3D bridge as an oblique view and a plan.
Bars are thick black, strings thin blue, deck strings grey and transverse members (those
joining the two planes) green. Node numbers are the 1-based numbers of the design output.

    plot_topology.py DESIGN.json -o PICTURE.png [--title TEXT] [--no-numbers]
"""
import argparse
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (the backend must be chosen first)

STYLE = {  # member category -> (colour, line width, z-order)
    "bar": ("black", 3.0, 3),
    "string": ("tab:blue", 1.0, 2),
    "deck_string": ("grey", 1.5, 1),
    "transverse_bar": ("tab:green", 3.0, 3),
    "transverse_string": ("tab:green", 0.8, 2),
}
LABELS = {
    "bar": "bar",
    "string": "string",
    "deck_string": "deck string",
    "transverse_bar": "transverse bar",
    "transverse_string": "transverse string",
}


def category(member, nodes):
    """Member type from the JSON; a member joining different z (the two planes) is transverse."""
    i, j = (k - 1 for k in member["nodes"])
    transverse = member.get("group") == "transverse" or abs(nodes[i][2] - nodes[j][2]) > 1e-9
    if transverse:
        return "transverse_bar" if member["type"] == "bar" else "transverse_string"
    return member["type"]


def draw(ax, design, project, numbers, fixed):
    """Draws every member and node of `design` on `ax`, with (u, v) = project(x, y, z)."""
    nodes = design["nodes"]
    seen = set()
    for m in sorted(design["members"], key=lambda m: STYLE[category(m, nodes)][2]):
        cat = category(m, nodes)
        colour, width, order = STYLE[cat]
        (u0, v0), (u1, v1) = (project(*nodes[k - 1]) for k in m["nodes"])
        ax.plot([u0, u1], [v0, v1], color=colour, lw=width, zorder=order,
                solid_capstyle="round", label=None if cat in seen else LABELS[cat])
        seen.add(cat)
    for k, xyz in enumerate(nodes, start=1):
        u, v = project(*xyz)
        ax.plot(u, v, marker="^" if k in fixed else "o", ms=7 if k in fixed else 3,
                color="tab:red" if k in fixed else "black", zorder=4)
        if numbers:
            ax.annotate(str(k), (u, v), textcoords="offset points", xytext=(3, 3),
                        fontsize=7, color="darkred", zorder=5)
    ax.grid(alpha=0.25)


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("design", help="design JSON from 'tbridge design ... -o'")
    parser.add_argument("-o", "--output", required=True, help="picture to write (.png, .svg, .pdf)")
    parser.add_argument("--title", help="figure title (default: from the topology)")
    parser.add_argument("--no-numbers", action="store_true", help="leave out node numbers")
    args = parser.parse_args(argv)
    try:
        with open(args.design) as f:
            design = json.load(f)
        nodes, topo = design["nodes"], design["topology"]
        design["members"]  # noqa: B018  (fail early on a file without members)
    except (OSError, ValueError, KeyError) as e:
        sys.exit(f"plot_topology: cannot read a design from {args.design}: {e}")
    fixed = set(topo.get("fixed_nodes", []))
    title = args.title or (
        f"n = {topo['n']}, p = {topo['p']}, beta = {topo['beta_deg']:g} deg, "
        f"{topo['planes']} plane{'s' if topo['planes'] > 1 else ''}: "
        f"{topo['nodes']} nodes, {topo['bars']} bars, {topo['strings']} strings, class {topo['class']}")
    numbers = not args.no_numbers
    spatial = any(abs(p[2]) > 1e-12 for p in nodes)
    span = max(p[0] for p in nodes) - min(p[0] for p in nodes)
    depth = max(p[1] for p in nodes) - min(p[1] for p in nodes)
    # Shallow bridges (depth ~ span/20) are stretched vertically by a whole factor so the
    # members stay apart; the axis label says by how much.
    stretch = max(1, round(0.25 * span / depth)) if depth > 0 else 1
    ylabel = "y [m]" if stretch == 1 else f"y [m], drawn {stretch}x taller"
    if not spatial:
        fig, ax = plt.subplots(figsize=(11, 1.8 + 10 * stretch * depth / span))
        draw(ax, design, lambda x, y, z: (x, y), numbers, fixed)
        ax.set_aspect(stretch)
        ax.set_xlabel("x [m]")
        ax.set_ylabel(ylabel)
        ax.legend(loc="lower right", fontsize=8)
    else:
        # Oblique view: plane z = w drawn up and to the right of plane z = 0, so both planes
        # and the rungs between them show; y is stretched as for planar bridges.
        width = max(p[2] for p in nodes) - min(p[2] for p in nodes)
        shift = 1.2 * stretch * depth / width  # plane B clears plane A's depth

        def oblique(x, y, z):
            return x + 0.12 * span * z / width, stretch * y + shift * z

        fig, (ax3, axp) = plt.subplots(2, 1, figsize=(11, 10), height_ratios=[1.6, 1])
        draw(ax3, design, oblique, numbers, fixed)
        ax3.set_aspect("equal")
        ax3.set_yticks([])
        ax3.set_title(f"oblique view: plane z = {width:g} m drawn above and right of plane z = 0;"
                      f" y drawn {stretch}x taller", fontsize=9)
        ax3.set_xlabel("x [m] (plane z = 0)")
        ax3.legend(loc="lower right", fontsize=8)
        draw(axp, design, lambda x, y, z: (x, z), numbers, fixed)
        axp.set_aspect("equal")
        axp.set_title("plan, seen from above (deck and bottom nodes of a station overlap)",
                      fontsize=9)
        axp.set_xlabel("x [m]")
        axp.set_ylabel("z [m]")
    fig.suptitle(title, fontsize=10)
    fig.tight_layout()
    fig.savefig(args.output, dpi=130)


if __name__ == "__main__":
    main(sys.argv[1:])
