#!/usr/bin/env python3
"""Work-precision figure and tables from bench_work_precision's output.

    python3 tools/plot_work_precision.py wp.csv docs/work_precision.png > table.md

The figure: one panel per n (scene "small"), run time against the deck-displacement error,
log-log, one line per integrator. Printed (markdown): the RK4 stability limit per n (from
omega_max, and the largest stable rung measured), and the fastest integrator for each
accuracy level per n and scene.
"""
import csv
import math
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

LEVELS = [1e-1, 1e-2, 1e-3, 1e-4]  # relative deck-displacement error
PERIOD_LEVELS = [1e-2, 1e-4, 1e-6]  # relative period error
STYLE = {"rk4": ("o-", "RK4 (dt ladder)"), "dopri5": ("s-", "DOPRI5 (rtol ladder)"),
         "sdirk3": ("^-", "SDIRK3 implicit (dt ladder)")}


def read(path):
    meta, rows = {}, []
    with open(path) as f:
        lines = f.read().splitlines()
    for line in lines:
        if line.startswith("#"):
            fields = dict(re.findall(r"(\w+)=(\S+)", line))
            meta[(int(fields["n"]), fields["scene"])] = fields
    body = [l for l in lines if not l.startswith("#")]
    for r in csv.DictReader(body):
        r["n"] = int(r["n"])
        r["parameter"] = float(r["parameter"])
        r["ok"] = r["status"] == "ok"
        for k in ("wall_s", "disp_error", "period_error"):
            r[k] = float(r[k]) if r[k] else math.nan
        rows.append(r)
    return meta, rows


def fastest(rows, key, level):
    good = [r for r in rows if r["ok"] and r[key] <= level]
    if not good:
        return "–"
    best = min(good, key=lambda r: r["wall_s"])
    return f"{best['method']} {best['parameter']:g} ({best['wall_s'] * 1e3:.3g} ms)"


def main():
    meta, rows = read(sys.argv[1])
    out = sys.argv[2]
    ns = sorted({r["n"] for r in rows if r["scene"] == "small"})
    cols = min(4, len(ns))
    fig, axes = plt.subplots((len(ns) + cols - 1) // cols, cols, figsize=(4 * cols, 3.3 * ((len(ns) + cols - 1) // cols)),
                             squeeze=False)
    for ax, n in zip(axes.flat, ns):
        for method, (fmt, label) in STYLE.items():
            pts = sorted((r["wall_s"], r["disp_error"]) for r in rows
                         if r["n"] == n and r["scene"] == "small" and r["method"] == method and r["ok"])
            if pts:
                ax.loglog([p[0] for p in pts], [max(p[1], 1e-12) for p in pts], fmt, label=label, ms=4)
        m = meta.get((n, "small"), {})
        if m:
            ax.axhline(float(m["ref_floor_disp"]), color="grey", lw=0.8, ls=":")
        ax.set_title(f"n = {n}" + (f", RK4 limit {float(m['rk4_limit']):.2g} s" if m else ""), fontsize=9)
        ax.set_xlabel("run time [s]", fontsize=8)
        ax.set_ylabel("deck displacement error (rel.)", fontsize=8)
        ax.grid(True, which="both", lw=0.3)
    for ax in list(axes.flat)[len(ns):]:
        ax.axis("off")
    axes.flat[0].legend(fontsize=7)
    fig.suptitle("Work-precision, class-1 bridges, 1e-4 m push, 0.5 s (dotted: reference floor)", fontsize=10)
    fig.tight_layout()
    fig.savefig(out, dpi=110)

    print("| n | nodes | members | omega_max [rad/s] | RK4 limit 2 sqrt(2)/omega_max [s] | largest stable RK4 rung [s] | smallest unstable rung [s] |")
    print("|---|---|---|---|---|---|---|")
    for n in ns:
        m = meta[(n, "small")]
        rk = [r for r in rows if r["n"] == n and r["scene"] == "small" and r["method"] == "rk4"]
        stable = [r["parameter"] for r in rk if r["ok"]]
        unstable = [r["parameter"] for r in rk if r["status"] == "unstable"]
        print(f"| {n} | {m['nodes']} | {m['members']} | {float(m['omega_max']):.4g} | {float(m['rk4_limit']):.3g} | "
              f"{max(stable) if stable else '–'} | {min(unstable) if unstable else '–'} |")
    print()
    for scene in ("small", "table5"):
        sn = sorted({r["n"] for r in rows if r["scene"] == scene})
        if not sn:
            continue
        print(f"Fastest run per accuracy level, scene `{scene}` (method, dt or rtol, run time):\n")
        head = " | ".join([f"disp <= {l:g}" for l in LEVELS] + [f"period <= {l:g}" for l in PERIOD_LEVELS])
        print(f"| n | ref floor (disp / period) | {head} |")
        print("|---" * (2 + len(LEVELS) + len(PERIOD_LEVELS)) + "|")
        for n in sn:
            sel = [r for r in rows if r["n"] == n and r["scene"] == scene]
            m = meta[(n, scene)]
            cells = [fastest(sel, "disp_error", l) for l in LEVELS] + [fastest(sel, "period_error", l) for l in PERIOD_LEVELS]
            print(f"| {n} | {float(m['ref_floor_disp']):.1e} / {float(m['ref_floor_period']):.1e} | " + " | ".join(cells) + " |")
        print()


if __name__ == "__main__":
    main()
