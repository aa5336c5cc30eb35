#!/usr/bin/python3
"""Figures from `tbridge sweep` outputs (OUTDIR/sweep.json) and `tbridge design` files.

  plot_sweep.py mass OUTDIR -o FIG.png [--prestrain 1]
      Objective against n, its parts stacked: bars, strings, deck strings, deck beams, joints
      (one deck prestrain, p and beta: the first of the grid unless given). The chosen design
      is marked; infeasible candidates are hatched.
  plot_sweep.py frequency OUTDIR -o FIG.png
      First linearised frequency against n, one line per deck prestrain (and beta, p), with
      the min_first_frequency_rad_s limit when the sweep has one.
  plot_sweep.py feasible OUTDIR -o FIG.png
      The grid over (n, deck prestrain): feasible candidates green, infeasible ones red with
      their first violated constraint, the chosen one circled; the objective in kg in each cell.
  plot_sweep.py premium OUTDIR -o FIG.png [--prestrain 1]
      The structure mass against n of a sweep of verified designs (sweep.verified): the first
      minimum-mass design, and on top of it the premium the checks added by resizing (static
      cases, dynamic runs), with the premium in per cent above each bar; the chosen design is
      marked, candidates that did not pass are hatched.
  plot_sweep.py bridge DESIGN.json -o FIG.png [--case NAME]
      A designed bridge (the file `tbridge design` or `tbridge check` writes) as an engineer
      checks it: every node numbered, every member labelled m1, m2, ... (its index in the
      file's members) and listed below with its name, type, utilisation, radius, mode and
      governing case (past 80 members, the 40 most utilised); members coloured by utilisation
      on 0..max(1, largest), those over 1 on a red scale, haloed and marked "!"; bars thick,
      strings thin, deck strings dashed; the supports drawn, their reaction envelope over the
      ultimate cases and the verdict with the governing member above. A planar bridge is
      drawn in x-y; a 3D one as an elevation (x-y) above a plan (x-z), nodes and members that
      one view puts on top of each other sharing a label.
      --case NAME marks the largest vertical deck deflection of a static case (the design
      file's deflection_max) and, where the Python module is importable
      (PYTHONPATH=build/python), draws the deflected shape: the case solved as the static
      check solves it (tbridge.case_nodes), its largest displacement drawn as a fifth of the
      bridge's depth. NAME
      is a label of the file ("sls_travelling at node 4"), or the
      sizing's "... at station K" (the K-th station along x), a travelling family's name
      (every station), or "max". FIG.png is written with FIG.svg beside it; -o FIG.svg
      writes the SVG alone.

Uses Debian's matplotlib (/usr/bin/python3).
"""
import argparse
import json
import math
import os
import re
import sys
import textwrap

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib import cm, colors  # noqa: E402


def load_sweep(out_dir):
    with open(out_dir.rstrip("/") + "/sweep.json") as f:
        data = json.load(f)
    if data.get("choice") is None:
        sys.exit("plot_sweep.py: %s/sweep.json is one shard; merge the shards first" % out_dir)
    return data


def series_key(row):
    return (row["p"], row["beta_deg"], row["deck_prestrain"])


def label_of(key, data):
    sweep = data["config"]["sweep"]
    parts = []
    if len(sweep["p"]) > 1:
        parts.append("p = %d" % key[0])
    if len(sweep["beta_deg"]) > 1:
        parts.append("beta = %g deg" % key[1])
    parts.append("design state" if key[2] == 1 else "deck prestrain %g" % key[2])
    return ", ".join(parts)


def plot_mass(args):
    data = load_sweep(args.dir)
    rows = rows_of(data, args.prestrain)
    ns = [r["n"] for r in rows]
    parts = [("bars", "bars", "#444444"), ("strings", "strings", "#1f77b4"),
             ("deck_strings", "deck strings", "#9ecae1"), ("deck_beams", "deck beams", "#bbbbbb"),
             ("joints", "joints", "#ff7f0e")]
    fig, ax = plt.subplots(figsize=(7, 4.5))
    bottom = [0.0] * len(rows)
    for key, name, colour in parts:
        values = [r["mass_kg"][key] for r in rows]
        bars = ax.bar(ns, values, bottom=bottom, color=colour, label=name, width=0.6)
        for bar, r in zip(bars, rows):
            if not r["feasible"]:
                bar.set_hatch("//")
                bar.set_edgecolor("#cc0000")
        bottom = [b + v for b, v in zip(bottom, values)]
    chosen = data["choice"].get("index")
    for r, top in zip(rows, bottom):
        ax.text(r["n"], top, "%.0f" % top, ha="center", va="bottom", fontsize=8)
        if r["index"] == chosen:
            ax.annotate("chosen", (r["n"], top), xytext=(0, 14), textcoords="offset points", ha="center",
                        fontsize=9, color="green", arrowprops=dict(arrowstyle="->", color="green"))
    ax.set_yscale("log")
    ax.set_xlabel("complexity n")
    ax.set_ylabel("mass [kg] (log scale)")
    ax.set_title("objective and its parts (%s); hatched: infeasible" % label_of(series_key(rows[0]), data))
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(args.output, dpi=120)


def rows_of(data, prestrain):
    """The ok rows of one series: the grid's first p and beta, deck prestrain `prestrain`."""
    sweep = data["config"]["sweep"]
    prestrain = prestrain if prestrain is not None else sweep["deck_prestrain"][0]
    rows = [r for r in data["rows"] if r["p"] == sweep["p"][0] and r["beta_deg"] == sweep["beta_deg"][0]
            and r["deck_prestrain"] == prestrain and r["ok"]]
    if not rows:
        sys.exit("plot_sweep.py: no rows with deck prestrain %g" % prestrain)
    return rows


def plot_premium(args):
    data = load_sweep(args.dir)
    if not data["config"]["sweep"].get("verified", False):
        sys.exit("plot_sweep.py: the sweep's designs are not verified (sweep.verified = false): no premium")
    rows = rows_of(data, args.prestrain)
    ns = [r["n"] for r in rows]
    first = [r["mass_kg"]["first_design"] for r in rows]
    premium = [r["mass_kg"]["structure"] - f for r, f in zip(rows, first)]
    fig, ax = plt.subplots(figsize=(7, 4.5))
    ax.bar(ns, first, color="#1f77b4", width=0.6, label="first minimum-mass design")
    tops = ax.bar(ns, premium, bottom=first, color="#ff7f0e", width=0.6, label="premium of the checks (resizing)")
    chosen = data["choice"].get("index")
    for bar, r, f, p in zip(tops, rows, first, premium):
        if not r["verified"]:
            bar.set_hatch("//")
            bar.set_edgecolor("#cc0000")
        label = "+%.0f %%" % (100 * p / f) + ("" if r["verified"] else " (fails)")
        ax.text(r["n"], f + p, label, ha="center", va="bottom", fontsize=8)
        if r["index"] == chosen:
            ax.annotate("chosen", (r["n"], f + p), xytext=(0, 30), textcoords="offset points", ha="center",
                        fontsize=9, color="green", arrowprops=dict(arrowstyle="->", color="green"))
    ax.set_xlabel("complexity n")
    ax.set_ylabel("structure mass [kg]")
    ax.set_title("structure mass: first design and the premium of verification (%s)" % label_of(series_key(rows[0]), data),
                 fontsize=10)
    ax.legend(fontsize=8, loc="upper left")
    fig.tight_layout()
    fig.savefig(args.output, dpi=120)


def plot_frequency(args):
    data = load_sweep(args.dir)
    series = {}
    for r in data["rows"]:
        if r["ok"] and r["first_frequency_rad_s"] is not None:
            series.setdefault(series_key(r), []).append(r)
    if not series:
        sys.exit("plot_sweep.py: no first frequencies in the sweep (set sweep.report.first_frequency)")
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for key, rows in sorted(series.items()):
        ax.plot([r["n"] for r in rows], [r["first_frequency_rad_s"] for r in rows], "o-", label=label_of(key, data))
    limit = data["config"]["sweep"]["constraints"]["min_first_frequency_rad_s"]
    if limit is not None:
        ax.axhline(limit, color="red", linestyle="--", label="min_first_frequency_rad_s = %g" % limit)
    ax.set_xlabel("complexity n")
    ax.set_ylabel("first linearised frequency [rad/s]")
    ax.set_title("lowest natural frequency about the design equilibrium")
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(args.output, dpi=120)


def plot_feasible(args):
    data = load_sweep(args.dir)
    sweep = data["config"]["sweep"]
    ns, ratios = sweep["n"], sweep["deck_prestrain"]
    fig, ax = plt.subplots(figsize=(1.4 * len(ns) + 2, 1.0 * len(ratios) + 1.8))
    chosen = data["choice"].get("index")
    for r in data["rows"]:
        if r["p"] != sweep["p"][0] or r["beta_deg"] != sweep["beta_deg"][0]:
            continue
        x, y = ns.index(r["n"]), ratios.index(r["deck_prestrain"])
        ok = r["ok"] and r["feasible"]
        ax.add_patch(plt.Rectangle((x - 0.45, y - 0.4), 0.9, 0.8, color="#8fd18f" if ok else "#f4a6a6"))
        why = "" if ok else (r["violated"][0] if r["violated"] else "failed")
        ax.text(x, y + 0.1, "%.0f kg" % r["mass_kg"]["objective"], ha="center", va="center", fontsize=8)
        ax.text(x, y - 0.18, why.replace("_", " "), ha="center", va="center", fontsize=6)
        if r["index"] == chosen:
            ax.add_patch(plt.Circle((x, y), 0.42, fill=False, color="green", linewidth=2))
    ax.set_xlim(-0.6, len(ns) - 0.4)
    ax.set_ylim(-0.6, len(ratios) - 0.4)
    ax.set_xticks(range(len(ns)), [str(n) for n in ns])
    ax.set_yticks(range(len(ratios)), ["%g%s" % (r, " (design)" if r == 1 else "") for r in ratios])
    ax.set_xlabel("complexity n")
    ax.set_ylabel("deck prestrain (rest/stretched)")
    ax.set_title("feasible (green) and infeasible (red) candidates; circled: chosen\n" +
                 "decided by: " + data["choice"]["binding"], fontsize=9)
    fig.tight_layout()
    fig.savefig(args.output, dpi=120)


# The design drawing. Members are coloured by utilisation (demand / resistance, the design
# file's verdict on each): 0 to 1 on one scale, above 1 on a red scale of its own and haloed,
# so that an overloaded member never shares a colour with a working one. A two-slope scale
# keeps 0..1 readable when a member is far past 1 (the slack measure reaches tens).
WIDTH = {"bar": 4.2, "deck_string": 2.2, "string": 1.3}
STYLE = {"bar": "-", "deck_string": (0, (4, 2)), "string": "-"}
UNCHECKED = "#9a9a9a"  # a member with no utilisation in the file
OVER = 1.0 + 1e-9  # over capacity as the verdict counts it: past 1 by more than rounding (design/verification.cc)


def utilisation_scale(largest):
    vmax = max(1.0, largest)
    below = [plt.get_cmap("viridis")(0.86 * i / 255) for i in range(256)]
    if vmax <= 1.0:
        return colors.ListedColormap(below), colors.Normalize(vmin=0.0, vmax=1.0)
    above = [plt.get_cmap("Reds")(0.5 + 0.5 * i / 255) for i in range(256)]
    return colors.ListedColormap(below + above), colors.TwoSlopeNorm(vmin=0.0, vcenter=1.0, vmax=vmax)


def support_marker():
    """A pinned support drawn under its node: triangle, ground line, hatching. The path's
    origin is the node, so the symbol hangs below it at any zoom."""
    from matplotlib.path import Path

    verts, codes = [(0, 0), (-0.55, -1), (0.55, -1), (0, 0)], [Path.MOVETO, Path.LINETO, Path.LINETO, Path.CLOSEPOLY]
    verts += [(-0.9, -1), (0.9, -1)]
    codes += [Path.MOVETO, Path.LINETO]
    for x in (-0.75, -0.4, -0.05, 0.3, 0.65):
        verts += [(x + 0.25, -1), (x - 0.05, -1.35)]
        codes += [Path.MOVETO, Path.LINETO]
    return Path(verts, codes)


def utilisation_of(member):
    u = member.get("utilisation")
    return None if u is None else float(u)


def deflection_entries(design, name):
    """The design file's deflection_max entries that `name` asks for.

    The static check labels a travelling case by the node its load stands on ("sls_travelling
    at node 4"); the sizing names the same position by its station ("... at station 4", as in
    the members' governing_case). Stations are numbered along x, as the check lists them, so
    station k is the k-th entry of that family. A family's bare name gives every station, and
    "max" the case with the largest deflection."""
    entries = design.get("deflection_max") or []
    if not entries:
        sys.exit("plot_sweep.py: the design file has no static check (deflection_max is empty)")
    if name == "max":
        return [max(entries, key=lambda e: e["deflection"])]
    exact = [e for e in entries if e["case"] == name]
    if exact:
        return exact
    station = re.fullmatch(r"(.+) at station (\d+)", name)
    if station:
        family = [e for e in entries if e["case"].startswith(station.group(1) + " at node ")]
        if 1 <= int(station.group(2)) <= len(family):
            return [family[int(station.group(2)) - 1]]
    family = [e for e in entries if e["case"].startswith(name + " at node ")]
    if family:
        return family
    names = []
    for e in entries:
        base = e["case"].split(" at node ")[0] + (" [at node K | at station K]" if " at node " in e["case"] else "")
        if base not in names:
            names.append(base)
    sys.exit("plot_sweep.py: no static deflection for case '%s' in the design file (a dynamic run has none);"
             " its cases: max, %s" % (name, ", ".join(names)))


def projection_groups(design, h, v):
    """Nodes and members as one view projects them: nodes that land on one point share a
    label; members that land on one segment share a line (the most utilised drawn, all named);
    members along the line of sight are left out and listed."""
    nodes = design["nodes"]
    extent = max(max(p[a] for p in nodes) - min(p[a] for p in nodes) for a in (h, v)) or 1.0

    def key(k):
        return (round(nodes[k][h] / (1e-9 * extent)), round(nodes[k][v] / (1e-9 * extent)))

    node_groups = {}
    for k in range(len(nodes)):
        node_groups.setdefault(key(k), []).append(k + 1)
    member_groups, hidden = {}, []
    for index, m in enumerate(design["members"], start=1):
        a, b = key(m["nodes"][0] - 1), key(m["nodes"][1] - 1)
        if a == b:
            hidden.append(index)
        else:
            member_groups.setdefault(tuple(sorted((a, b))), []).append(index)
    return node_groups, member_groups, hidden


def case_shape(path, label):
    """The nodes under one static case, solved as the static check solves it, through the Python
    module (tbridge.case_nodes: the nonlinear static problem from the reference state), or None
    where the module is not importable (PYTHONPATH=build/python)."""
    try:
        import tbridge
    except ImportError:
        return None
    return tbridge.case_nodes(tbridge.load_design(path), label).tolist()


def draw_shape(ax, design, shape, h, v, scale):
    """The deflected shape: each node moved from the drawn geometry by `scale` times its
    displacement under the case, every member drawn between the moved nodes."""
    nodes = design["nodes"]
    moved = [[p[a] + scale * (q[a] - p[a]) for a in range(3)] for p, q in zip(nodes, shape)]
    for m in design["members"]:
        a, b = moved[m["nodes"][0] - 1], moved[m["nodes"][1] - 1]
        ax.plot([a[h], b[h]], [a[v], b[v]], "-", color="#7a0077", linewidth=0.9, alpha=0.8, zorder=8)


def draw_view(ax, design, h, v, cmap, norm, labelled, deflections):
    """One projection of the bridge onto axes h (across the page) and v (up the page). The
    labels carry SVG ids, "elevation-node-1-4", "plan-member-3-9", for tools reading the SVG."""
    view = "elevation" if v == 1 else "plan"
    nodes = design["nodes"]
    members = design["members"]
    fixed = set(design["topology"]["fixed_nodes"])
    node_groups, member_groups, hidden = projection_groups(design, h, v)

    def point(k):  # 1-based node
        return nodes[k - 1][h], nodes[k - 1][v]

    def colour(u):
        return UNCHECKED if u is None else cmap(norm(u if u > OVER else min(u, 1.0)))

    for group in member_groups.values():
        # The most utilised member of a shared segment is drawn last, on top.
        group = sorted(group, key=lambda i: utilisation_of(members[i - 1]) or 0.0)
        (x0, y0), (x1, y1) = point(members[group[0] - 1]["nodes"][0]), point(members[group[0] - 1]["nodes"][1])
        worst = max((utilisation_of(members[i - 1]) or 0.0) for i in group)
        for i in group:
            m = members[i - 1]
            a, b = point(m["nodes"][0]), point(m["nodes"][1])
            z = {"bar": 4, "deck_string": 3, "string": 2}[m["type"]]
            ax.plot([a[0], b[0]], [a[1], b[1]], linestyle=STYLE[m["type"]], color=colour(utilisation_of(m)),
                    linewidth=WIDTH[m["type"]], solid_capstyle="round", zorder=z)
        if worst > OVER:
            ax.plot([x0, x1], [y0, y1], "-", color="red", alpha=0.3, linewidth=WIDTH["bar"] + 7,
                    solid_capstyle="round", zorder=1)
        shown = [i for i in group if i in labelled]
        if shown:
            over = worst > OVER
            ax.text(0.5 * (x0 + x1), 0.5 * (y0 + y1), "/".join("m%d" % i for i in shown) + (" !" if over else ""),
                    fontsize=6.5, ha="center", va="center", color="#b00000" if over else "#303030",
                    fontweight="bold" if over else "normal", zorder=6,
                    gid="%s-member-%s" % (view, "-".join(map(str, shown))),
                    bbox=dict(boxstyle="square,pad=0.15", fc="white", ec="#b00000" if over else "#aaaaaa",
                              lw=0.5, alpha=0.85))

    # Node labels sit away from the node's members (in axis-fraction units, as the view's
    # two scales differ), so a label does not cover what meets there.
    xs = [p[h] for p in nodes]
    ys = [p[v] for p in nodes]
    sx = (max(xs) - min(xs)) or 1.0
    sy = (max(ys) - min(ys)) or 1.0
    ax.plot(xs, ys, "o", color="black", markersize=3, zorder=7)
    for group in node_groups.values():
        x, y = point(group[0])
        dx = dy = 0.0
        for m in members:
            for a, b in (m["nodes"], m["nodes"][::-1]):
                if a in group:
                    ox, oy = point(b)
                    ux, uy = (ox - x) / sx, (oy - y) / sy
                    norm_u = math.hypot(ux, uy)
                    if norm_u > 1e-9:
                        dx, dy = dx - ux / norm_u, dy - uy / norm_u
        length = math.hypot(dx, dy)
        dx, dy = (dx / length, dy / length) if length > 0.2 else (0.0, 1.0)
        if v == 2:  # the plan's z axis points down the page
            dy = -dy
        ax.annotate(", ".join(str(k) for k in group), (x, y), xytext=(11 * dx, 11 * dy), textcoords="offset points",
                    ha="center", va="center", fontsize=7.5, fontweight="bold", zorder=8,
                    gid="%s-node-%s" % (view, "-".join(map(str, group))),
                    bbox=dict(boxstyle="circle,pad=0.15" if len(group) == 1 else "round,pad=0.2", fc="white",
                              ec="black", lw=0.6))
    supports = [point(k) for k in sorted(fixed)]
    if v == 1:
        ax.plot([p[0] for p in supports], [p[1] for p in supports], linestyle="none", marker=support_marker(),
                markersize=26, markerfacecolor="white", markeredgecolor="black", markeredgewidth=1.0, zorder=5)
    else:
        ax.plot([p[0] for p in supports], [p[1] for p in supports], linestyle="none", marker="s", markersize=11,
                markerfacecolor="#c8c8c8", markeredgecolor="black", zorder=5)

    # The design file gives each static case's largest vertical deck deflection and its node,
    # not the displaced nodes: an arrow at that node with the value stands for the case.
    if v == 1:
        for e in deflections:
            if e["node"] is None:
                continue
            x, y = point(e["node"])
            ax.annotate("%.2f mm" % (1e3 * e["deflection"]) + ("" if e["converged"] else " (not converged)"),
                        (x, y), xytext=(0, -34), textcoords="offset points", ha="center", va="top", fontsize=7.5,
                        color="#7a0077", fontweight="bold", zorder=9,
                        arrowprops=dict(arrowstyle="<|-", color="#7a0077", lw=1.6, shrinkA=0, shrinkB=3),
                        bbox=dict(boxstyle="round,pad=0.15", fc="white", ec="none", alpha=0.85))
    return hidden


def bridge_outputs(output):
    """The files to write: FIG.svg alone, or FIG.png and beside it FIG.svg, or another format alone."""
    stem, ext = os.path.splitext(output)
    if ext.lower() == ".png":
        return [output, stem + ".svg"]
    return [output]


def plot_bridge(args):
    with open(args.design) as f:
        design = json.load(f)
    nodes = design["nodes"]
    members = design["members"]
    topo = design["topology"]
    planar = topo.get("planes", 1) == 1 and all(abs(p[2]) < 1e-12 for p in nodes)
    deflections = deflection_entries(design, args.case) if args.case else []
    shape = case_shape(args.design, deflections[0]["case"]) if len(deflections) == 1 else None
    # Drawn so that the largest displacement shows as a fifth of the bridge's depth (the views
    # stretch y, so a share of the span would cross the drawing).
    moves = [math.dist(p, q) for p, q in zip(design["nodes"], shape)] if shape else [0.0]
    depth = (max(p[1] for p in design["nodes"]) - min(p[1] for p in design["nodes"])) or design["config"]["bridge"]["span"]
    shape_scale = 0.2 * depth / max(moves) if max(moves) > 0 else 1.0

    checked = [u for u in (utilisation_of(m) for m in members) if u is not None]
    largest = max(checked, default=0.0)
    cmap, norm = utilisation_scale(largest if largest > OVER else 1.0)
    # A table of every member, as long as it fits a page; beyond, the most utilised, and only
    # they are labelled in the drawing.
    order = sorted(range(1, len(members) + 1), key=lambda i: -(utilisation_of(members[i - 1]) or -1.0))
    listed = sorted(order[:40]) if len(members) > 80 else list(range(1, len(members) + 1))
    labelled = set(listed)
    governing = order[0]

    # Each level of n halves the smallest modules' depth: the views grow taller past n = 3.
    grow = 0.6 * max(0, topo["n"] - 3)
    views = [("elevation (x-y)", 0, 1, 3.4 + grow)] if planar else [
        ("elevation (x-y), seen from +z: the planes z = %s m overlap" %
         " and ".join("%g" % z for z in sorted({round(p[2], 9) for p in nodes})), 0, 1, 3.0 + grow),
        ("plan (x-z), seen from above: deck and substructure overlap", 0, 2, 2.6 + grow)]

    # Layout in inches: header, legend, the views, the member table.
    # The drawing widens with the number of distinct positions along x, so that the labels of
    # a finely divided bridge keep apart (n = 5 has 33: 20 inches).
    stations = len({round(p[0] / (1e-9 * design["config"]["bridge"]["span"])) for p in nodes})
    width, left, right = min(40.0, max(13.0, 0.6 * stations)), 0.9, 1.7
    columns = max(2, int((width - left - 0.3) / 6.2))  # a table row is about 6 inches
    rows = math.ceil(len(listed) / columns)
    # Header: what the bridge is, its verdict and the member that governs it.
    verdict = design.get("verdict", {})
    outcome = verdict.get("outcome", "no verdict")
    g = members[governing - 1]
    kinds = "planar" if planar else "%d planes" % topo.get("planes", 2)
    line1 = ("n = %d, p = %d, beta = %g deg, %s, span %g m: structure %.0f kg, total %.0f kg "
             "(%d nodes, %d bars, %d strings)"
             % (topo["n"], topo["p"], topo["beta_deg"], kinds, design["config"]["bridge"]["span"],
                design["mass"]["structure"], design["mass"]["total"], len(nodes), topo["bars"], topo["strings"]))
    line2 = ("verdict %s: largest utilisation %.4g in m%d (%s, %s), %s, governing case %s"
             % (outcome, utilisation_of(g) or 0.0, governing, g["name"], g["type"].replace("_", " "), g["mode"],
                g["governing_case"]))
    checks = verdict.get("checks", {})
    line3 = "checks: " + ", ".join("%s %s" % (k.replace("_", " "), s.replace("_", " ")) for k, s in checks.items())
    over = [i for i in order if (utilisation_of(members[i - 1]) or 0.0) > OVER]
    if over:
        # As many as the line holds (about 15 characters an inch at this size).
        room, shown = int(15 * (width - left - 0.3)) - len(line3) - 30, []
        for i in over:
            item = "m%d %s (%.3g)" % (i, members[i - 1]["name"], utilisation_of(members[i - 1]))
            if sum(len(t) + 2 for t in shown) + len(item) > room:
                break
            shown.append(item)
        line3 += ";  %d over 1: " % len(over) + ", ".join(shown) + (", ..." if len(shown) < len(over) else "")
    lines = [(line1, 10.5, "black", "bold"), (line2, 9.5, "#006400" if outcome == "PASS" else "#b00000", "bold"),
             (line3, 8, "black", "normal")]
    if deflections:
        ratio = design["config"]["loads"]["deflection_limit"]
        limit = design["config"]["bridge"]["span"] / ratio
        states = {c["name"]: c["limit_state"] for c in design.get("cases", [])}
        # One case, or a travelling family's stations each marked and the largest named.
        e = max(deflections, key=lambda e: e["deflection"])
        sls = states.get(e["case"].split(" at node ")[0]) == "serviceability"
        text = ("largest deflection of %s: " % e["case"] if len(deflections) == 1 else
                "largest deflection at each of the %d stations of %s; the largest, %s: " %
                (len(deflections), args.case, e["case"]))
        text += "%.2f mm at node %d" % (1e3 * e["deflection"], e["node"]) if e["node"] else "none (0 mm)"
        text += ", limit span/%g = %.1f mm" % (ratio, 1e3 * limit) if sls else ""
        text += ", %d slack string%s" % (e["slack_strings"], "s" * (e["slack_strings"] > 1)) if e["slack_strings"] else ""
        stalled = [d["case"] for d in deflections if not d["converged"]]
        if stalled:
            text += "; not converged: " + ", ".join(stalled)
        lines.append((text + (" (purple: the deflected shape, displacements x%.3g)" % shape_scale if shape else
                              " (the deflected shape needs the Python module: PYTHONPATH=build/python)"),
                      8, "#7a0077", "normal"))
    # The supports' reactions: the chosen case's, else their envelope over the ultimate cases.
    chosen = deflections[0]["case"] if len(deflections) == 1 else None
    case_reactions = [r for r in design.get("reactions", []) if r["case"] == chosen]
    if case_reactions:
        lines.append(("support reactions of %s [kN]: " % chosen + "; ".join(
            "node %d H %.4g, V %.3g" % (r["node"], 1e-3 * r["force"][0], 1e-3 * r["force"][1])
            + (", z %.3g" % (1e-3 * r["force"][2]) if not planar else "") for r in case_reactions), 8, "black", "normal"))
    else:
        envelope = (design.get("reaction_envelope") or {}).get("supports", [])
        if envelope:
            lines.append(("support reactions, ULS envelope [kN]: " + "; ".join(
                "node %d V %.3g..%.3g, H %.4g..%.4g" % (r["node"], 1e-3 * r["y"]["min"], 1e-3 * r["y"]["max"],
                                                         1e-3 * r["x"]["min"], 1e-3 * r["x"]["max"])
                + (", z %.3g..%.3g" % (1e-3 * r["z"]["min"], 1e-3 * r["z"]["max"]) if not planar else "")
                for r in envelope), 8, "black", "normal"))
    # Long lines (four supports' reactions, three stations' deflections) wrap to the page, at
    # about 0.6 em a character.
    lines = [(part, size, colour, weight) for text, size, colour, weight in lines
             for part in textwrap.wrap(text, int((width - left - 0.3) * 72 / (0.6 * size)), subsequent_indent="    ",
                                           break_on_hyphens=False)]

    header, legend_h, gap, table_h = 0.35 + 0.25 * len(lines), 0.45, 0.7, 0.55 + 0.148 * (rows + 1)
    height = header + legend_h + sum(view[3] + gap for view in views) + table_h
    fig = plt.figure(figsize=(width, height))
    top = height - header - legend_h
    axes = []
    for title, h, v, view_h in views:
        ax = fig.add_axes([left / width, (top - view_h) / height, (width - left - right) / width, view_h / height])
        hidden = draw_view(ax, design, h, v, cmap, norm, labelled, deflections)
        if shape:
            draw_shape(ax, design, shape, h, v, shape_scale)
        note = ("; along the line of sight, not drawn here: " + ", ".join("m%d" % i for i in hidden)) if hidden else ""
        ax.set_title(title + note, fontsize=8.5, loc="left")
        ax.set_xlabel("x [m] (along the span)")
        ax.set_ylabel("y [m] (up)" if v == 1 else "z [m] (across)")
        ax.margins(x=0.03, y=0.2 if v == 1 else 0.25)
        if v == 2:
            ax.invert_yaxis()
        ax.grid(alpha=0.15)
        axes.append(ax)
        top -= view_h + gap
    for ax in axes:
        # The two scales differ; say by how much, as an engineer reads a distorted drawing.
        (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
        bbox = ax.get_position()
        ratio = (abs(x1 - x0) / (bbox.width * width)) / (abs(y1 - y0) / (bbox.height * height))
        if ratio > 1.5:
            ax.set_ylabel(ax.get_ylabel() + "\nscale x%.0f of x" % ratio)

    first, last = axes[0].get_position(), axes[-1].get_position()
    cax = fig.add_axes([(width - right + 0.25) / width, last.y0, 0.18 / width, first.y1 - last.y0])
    bar = fig.colorbar(cm.ScalarMappable(norm=norm, cmap=cmap), cax=cax)
    bar.set_label("utilisation (demand / resistance)", fontsize=8)
    ticks = [0, 0.25, 0.5, 0.75, 1.0] + ([largest] if largest > OVER else [])
    bar.set_ticks(ticks, labels=["%g" % t if t <= 1 else "%.3g" % t for t in ticks])
    bar.ax.axhline(1.0, color="black", linewidth=1.2)
    bar.ax.tick_params(labelsize=7.5)

    from matplotlib.lines import Line2D

    handles = [Line2D([], [], color="#555555", lw=WIDTH["bar"], label="bar"),
               Line2D([], [], color="#555555", lw=WIDTH["string"], label="string"),
               Line2D([], [], color="#555555", lw=WIDTH["deck_string"], linestyle=STYLE["deck_string"],
                      label="deck string"),
               Line2D([], [], color="red", alpha=0.3, lw=WIDTH["bar"] + 3, label="utilisation > 1 (label !)"),
               Line2D([], [], linestyle="none", marker=support_marker(), markersize=16, markerfacecolor="white",
                      markeredgecolor="black", label="support (fixed node)" if planar else "support (plan: square)"),
               Line2D([], [], linestyle="none", marker="o", markersize=8, markerfacecolor="white",
                      markeredgecolor="black", label="node number"),
               Line2D([], [], linestyle="none", marker="s", markersize=8, markerfacecolor="white",
                      markeredgecolor="#aaaaaa", label="member m# (table below)")]
    if deflections:
        handles.append(Line2D([], [], color="#7a0077", marker="v", lw=1.6, label="largest deflection of the case"))
    if any(utilisation_of(m) is None for m in members):
        handles.append(Line2D([], [], color=UNCHECKED, lw=2, label="not checked"))
    fig.legend(handles=handles, loc="center", ncol=len(handles), fontsize=7.5, frameon=False,
               bbox_to_anchor=(0.5, (height - header - 0.3 * legend_h) / height))

    for k, (text, size, colour, weight) in enumerate(lines):
        fig.text(left / width, 1 - (0.22 + 0.25 * k) / height, text, fontsize=size, color=colour, fontweight=weight,
                 va="top")

    # The member table, in columns; rows over 1 in red, the governing member in bold.
    y0 = table_h - 0.1
    fig.text(left / width, y0 / height, "members%s (utilisation: the largest over every case and run; radius of a "
             "solid section)" % ("" if len(listed) == len(members) else ", the %d most utilised of %d" %
                                 (len(listed), len(members))), fontsize=8, fontweight="bold", va="top")
    # Each cell is its own text at its own place: an SVG viewer collapses runs of spaces, so a
    # padded line would lose its columns there. Offsets in characters of the 7 pt monospace.
    char = 0.6 * 7 / 72  # [in]
    cells = [("", 0, "left"), ("name", 5, "left"), ("type", 13, "left"), ("util.", 32, "right"),
             ("r [mm]", 40, "right"), ("mode", 42, "left"), ("governing case", 52, "left")]
    col_w = (width - left - 0.3) / columns
    for c in range(columns):
        chunk = listed[c * rows:(c + 1) * rows]
        if not chunk:
            continue
        x0 = left + c * col_w
        rows_text = [([name for name, _, _ in cells], "#444444", "normal")]
        for i in chunk:
            m = members[i - 1]
            u = utilisation_of(m)
            rows_text.append((["m%d" % i, m["name"], m["type"], "-" if u is None else "%.4f" % u,
                               "%.1f" % (1e3 * m["radius"]), m.get("mode") or "-", m.get("governing_case") or "-"],
                              "#b00000" if (u or 0.0) > OVER else "black", "bold" if i == governing else "normal"))
        for r, (values, colour, weight) in enumerate(rows_text):
            y = (y0 - 0.2 - 0.148 * r) / height
            for value, (_, offset, align) in zip(values, cells):
                fig.text((x0 + offset * char) / width, y, value, fontsize=7, family="monospace", va="top", ha=align,
                         color=colour, fontweight=weight)

    # Text stays text in the SVG (searchable, editable), not glyph outlines.
    plt.rcParams["svg.fonttype"] = "none"
    for path in bridge_outputs(args.output):
        fig.savefig(path, dpi=120)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = parser.add_subparsers(dest="command", required=True)
    for name, fn in (("mass", plot_mass), ("premium", plot_premium), ("frequency", plot_frequency),
                     ("feasible", plot_feasible)):
        p = sub.add_parser(name)
        p.add_argument("dir")
        p.add_argument("-o", "--output", required=True)
        if name in ("mass", "premium"):
            p.add_argument("--prestrain", type=float, default=None)
        p.set_defaults(fn=fn)
    p = sub.add_parser("bridge")
    p.add_argument("design")
    p.add_argument("-o", "--output", required=True)
    p.add_argument("--case", default=None,
                   help="mark the largest deck deflection of this static case (a deflection_max label, "
                        "'NAME at station K', a travelling family's NAME or 'max'), and draw its deflected "
                        "shape where the Python module is importable (PYTHONPATH=build/python)")
    p.set_defaults(fn=plot_bridge)
    args = parser.parse_args()
    args.fn(args)


if __name__ == "__main__":
    main()
