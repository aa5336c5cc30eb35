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
  plot_sweep.py bridge DESIGN.json -o FIG.png
      A designed bridge: member width proportional to its radius, colour to its force
      (compression of bars, tension of strings), deck strings dashed.

Uses Debian's matplotlib (/usr/bin/python3).
"""
import argparse
import json
import sys

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


def plot_bridge(args):
    with open(args.design) as f:
        design = json.load(f)
    nodes = design["nodes"]
    members = design["members"]
    radius_max = max(m["radius"] for m in members)
    norm = colors.Normalize(vmin=0, vmax=max(m["force"] for m in members))
    cmap = plt.get_cmap("viridis")
    fig, ax = plt.subplots(figsize=(10, 3.6))
    for m in members:
        i, j = m["nodes"][0] - 1, m["nodes"][1] - 1
        width = 0.6 + 7.0 * m["radius"] / radius_max
        style = "--" if m["type"] == "deck_string" else "-"
        ax.plot([nodes[i][0], nodes[j][0]], [nodes[i][1], nodes[j][1]], style, color=cmap(norm(m["force"])),
                linewidth=width, solid_capstyle="round", zorder=3 if m["type"] == "bar" else 2)
    xs = [p[0] for p in nodes]
    ys = [p[1] for p in nodes]
    ax.plot(xs, ys, "o", color="black", markersize=2.5, zorder=4)
    fixed = design["topology"]["fixed_nodes"]
    ax.plot([nodes[k - 1][0] for k in fixed], [nodes[k - 1][1] for k in fixed], "^", color="black", markersize=9)
    fig.colorbar(cm.ScalarMappable(norm=norm, cmap=cmap), ax=ax, label="force [N] (bars: compression, strings: tension)")
    topo = design["topology"]
    ax.set_title("n = %d, p = %d, beta = %g deg: width ~ radius (largest %.1f mm), total %.0f kg" %
                 (topo["n"], topo["p"], topo["beta_deg"], 1000 * radius_max, design["mass"]["total"]))
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m] (vertical scale exaggerated)")
    ax.margins(y=0.15)
    fig.tight_layout()
    fig.savefig(args.output, dpi=120)


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
    p.set_defaults(fn=plot_bridge)
    args = parser.parse_args()
    args.fn(args)


if __name__ == "__main__":
    main()
