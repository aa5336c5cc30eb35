#!/usr/bin/python3
"""Figures from `tbridge simulate` outputs (OUTDIR/summary.json and OUTDIR/history.csv).

  plot_dynamics.py snapshots OUTDIR -o FIG.png [--times 0.02,0.05,0.1] [--scale 3]
      The bridge at chosen times, displacements amplified by --scale: initial shape dashed
      black, bars thick, taut strings blue, slack strings (length < rest length) dashed red
      (the paper's Figure 5). Planar bridges in the x-y plane; a 3D bridge as one oblique
      view per time, side by side (the paper's Figures 8 and 10), with the deck nodes'
      displacement in mm noted.
  plot_dynamics.py deck OUTDIR -o FIG.png [--axis y|x|z]
      Displacement histories of the deck nodes along an axis, from the run's starting
      positions (the paper's Figure 6 for y, Figures 9 and 11 for the 3D runs). Dashed
      vertical lines mark the times at which a timed load (dynamics.loads) switches on or off.

The deck nodes of a designed bridge are the free ends of its deck strings (group "deck" in
summary.json's model.members.strings); those of a custom scene are its structure.deck_nodes.

Record every free node (dynamics.record.nodes) to draw snapshots. Uses Debian's matplotlib
(/usr/bin/python3).
"""
import argparse
import csv
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def load(outdir):
    with open(os.path.join(outdir, "summary.json")) as f:
        summary = json.load(f)
    with open(os.path.join(outdir, "history.csv")) as f:
        rows = list(csv.reader(f))
    header, data = rows[0], [[float(v) for v in r] for r in rows[1:]]
    return summary, header, data


def columns(header):
    """Maps (node, axis) -> column index for the recorded nodes (1-based node numbers)."""
    out = {}
    for k, name in enumerate(header[1:], start=1):
        out[(int(name[1:]), "xyz".index(name[0]))] = k
    return out


def positions_at(summary, header, row, scale):
    """Node positions (list of [x, y, z]) at a history row, displacement amplified."""
    base = summary["model"]["members"]["positions"]
    cols = columns(header)
    pos = [list(p) for p in base]
    for (node, axis), k in cols.items():
        pos[node - 1][axis] = base[node - 1][axis] + scale * (row[k] - base[node - 1][axis])
    return pos, cols


def true_positions(summary, cols, row):
    base = summary["model"]["members"]["positions"]
    pos = [list(p) for p in base]
    for (node, axis), k in cols.items():
        pos[node - 1][axis] = row[k]
    return pos


def is_3d(members):
    return any(abs(p[2]) > 1e-12 for p in members["positions"])


def deck_nodes(summary):
    """The free deck nodes (1-based, ascending) as the run's output names them.

    summary.json lists no deck nodes of its own, and the starting positions cannot show them:
    a run of an engineering config starts from the loaded equilibrium, where the deck has
    sagged below y = 0. The deck strings can: they join the supports and the deck nodes and
    nothing else, so their free ends are the deck. A custom scene has no deck strings; its
    config names its deck (structure.deck_nodes), echoed in the summary."""
    members = summary["model"]["members"]
    fixed = set(members["fixed"])
    structure = summary["config"].get("structure")
    if structure is not None:
        return sorted(v for v in structure.get("deck_nodes", []) if v not in fixed)
    return sorted({v for s in members["strings"] if s.get("group") == "deck" for v in s["nodes"]} - fixed)


def snapshots_3d(args, summary, header, data, times):
    """One oblique 3D view per time: x along the span, z across, y up."""
    from mpl_toolkits.mplot3d import Axes3D  # noqa: F401  (registers the projection)

    members = summary["model"]["members"]
    base = members["positions"]
    fig = plt.figure(figsize=(5.2 * len(times), 4.4))
    for k, t in enumerate(times):
        ax = fig.add_subplot(1, len(times), k + 1, projection="3d")
        row = min(data, key=lambda r: abs(r[0] - t))
        pos, cols = positions_at(summary, header, row, args.scale)
        real = true_positions(summary, cols, row)

        def line(i, j, points, *style, **kw):
            ax.plot([points[i][0], points[j][0]], [points[i][2], points[j][2]],
                    [points[i][1], points[j][1]], *style, **kw)

        for b in members["bars"]:
            i, j = (n - 1 for n in b["nodes"])
            line(i, j, base, "k--", lw=0.5)
            line(i, j, pos, "k-", lw=2.2)
        slack = 0
        for s in members["strings"]:
            i, j = (n - 1 for n in s["nodes"])
            is_slack = math.dist(real[i], real[j]) < s["rest_length_m"]
            slack += is_slack
            colour = "r--" if is_slack else ("g-" if s.get("group") == "transverse" else "b-")
            line(i, j, pos, colour, lw=0.7)
        for v in members["fixed"]:
            p = base[v - 1]
            ax.plot([p[0]], [p[2]], [p[1]], "k^", ms=6)
        deck = [v - 1 for v in deck_nodes(summary)]
        peak = max((math.dist(real[v], base[v]) for v in deck), default=0.0)
        ax.set_title(f"t = {row[0]:.4f} s   x{args.scale:g}\nlargest deck displacement {1e3 * peak:.3f} mm"
                     + (f", {slack} slack" if slack else ""), fontsize=9)
        ax.set_xlabel("x [m]")
        ax.set_ylabel("z [m]")
        ax.set_zlabel("y [m]")
        xs = [p[0] for p in base]
        # The planes' z to the mm: a run from the loaded equilibrium starts them off z = 0 and
        # z = width by a fraction of a micrometre, which would give each node its own tick.
        zs = sorted({round(p[2], 3) + 0.0 for p in base})
        ax.set_yticks(zs)
        ax.set_box_aspect((max(xs) - min(xs), 4.0, 3.0))
        ax.view_init(elev=18, azim=-60)
    fig.tight_layout()
    fig.savefig(args.output, dpi=110)


def snapshots(args):
    summary, header, data = load(args.outdir)
    members = summary["model"]["members"]
    recorded = {node for node, _ in columns(header)}
    free = [v + 1 for v in range(len(members["positions"])) if v + 1 not in members["fixed"]]
    missing = [v for v in free if v not in recorded]
    if missing:
        sys.exit(f"plot_dynamics: nodes {missing} were not recorded; set dynamics.record.nodes to every free node")
    times = [float(t) for t in args.times.split(",")]
    if is_3d(members):
        snapshots_3d(args, summary, header, data, times)
        return
    fig, axes = plt.subplots(len(times), 1, figsize=(9, 2.2 * len(times)), squeeze=False)
    base = members["positions"]
    for ax, t in zip(axes[:, 0], times):
        row = min(data, key=lambda r: abs(r[0] - t))
        pos, cols = positions_at(summary, header, row, args.scale)
        real = true_positions(summary, cols, row)
        for b in members["bars"]:
            i, j = (n - 1 for n in b["nodes"])
            ax.plot([base[i][0], base[j][0]], [base[i][1], base[j][1]], "k--", lw=0.8)
            ax.plot([pos[i][0], pos[j][0]], [pos[i][1], pos[j][1]], "k-", lw=2.5)
        slack = 0
        for s in members["strings"]:
            i, j = (n - 1 for n in s["nodes"])
            ax.plot([base[i][0], base[j][0]], [base[i][1], base[j][1]], "k--", lw=0.5)
            length = math.dist(real[i], real[j])
            is_slack = length < s["rest_length_m"]
            slack += is_slack
            ax.plot([pos[i][0], pos[j][0]], [pos[i][1], pos[j][1]],
                    "r--" if is_slack else "b-", lw=1.2 if is_slack else 0.9)
        for v in members["fixed"]:
            ax.plot(base[v - 1][0], base[v - 1][1], "k^", ms=8)
        ax.set_title(f"t = {row[0]:.4f} s   ({slack} slack strings; displacements x{args.scale:g})",
                     fontsize=9)
        ax.set_aspect("auto")
        ax.set_ylabel("y [m]")
    axes[-1, 0].set_xlabel("x [m]")
    fig.tight_layout()
    fig.savefig(args.output, dpi=110)


def deck(args):
    summary, header, data = load(args.outdir)
    members = summary["model"]["members"]
    base = members["positions"]
    axis = "xyz".index(args.axis)
    cols = columns(header)
    deck = deck_nodes(summary)
    if not deck:
        sys.exit("plot_dynamics: the run has no deck nodes (no deck strings; a scene sets structure.deck_nodes)")
    nodes = [v for v in deck if (v, axis) in cols]
    if not nodes:
        sys.exit(f"plot_dynamics: no deck node was recorded (deck nodes {deck}; set dynamics.record.nodes)")
    fig, ax = plt.subplots(figsize=(9, 3.6))
    t = [r[0] for r in data]
    # The 3D bridge's second plane dashed: the nodes beyond the middle of the z range (a
    # loaded start may have moved the planes off z = 0 and z = width by a little).
    z_mid = 0.5 * (min(p[2] for p in base) + max(p[2] for p in base))
    for v in nodes:
        k = cols[(v, axis)]
        plane_b = is_3d(members) and base[v - 1][2] > z_mid
        ax.plot(t, [1e3 * (r[k] - base[v - 1][axis]) for r in data], "--" if plane_b else "-",
                lw=1.0, label=f"node {v}")
    duration = summary["config"]["dynamics"]["duration"]
    switches = sorted({t for load in summary["config"]["dynamics"].get("loads", [])
                       for t in (load["t_start"], load["t_end"]) if 0 < t < duration})
    for ts in switches:
        ax.axvline(ts, color="k", ls="--", lw=0.8)
    ax.set_xlabel("t [s]")
    ax.set_ylabel(f"{args.axis} displacement [mm]")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, ncol=min(len(nodes), 6))
    if args.title:
        ax.set_title(args.title, fontsize=9)
    fig.tight_layout()
    fig.savefig(args.output, dpi=110)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = parser.add_subparsers(dest="command", required=True)
    p = sub.add_parser("snapshots")
    p.add_argument("outdir")
    p.add_argument("-o", "--output", required=True)
    p.add_argument("--times", default="0.02,0.05,0.1")
    p.add_argument("--scale", type=float, default=3.0)
    p.set_defaults(run=snapshots)
    p = sub.add_parser("deck")
    p.add_argument("outdir")
    p.add_argument("-o", "--output", required=True)
    p.add_argument("--axis", default="y", choices=["x", "y", "z"])
    p.add_argument("--title", default="")
    p.set_defaults(run=deck)
    args = parser.parse_args()
    args.run(args)


if __name__ == "__main__":
    main()
