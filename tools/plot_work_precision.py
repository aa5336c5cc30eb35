#!/usr/bin/env python3
"""Work-precision figure and tables from bench_work_precision's output.

    python3 tools/plot_work_precision.py wp.csv docs/work_precision.png > table.md

The figure: per scene (planar n with the 1e-4 m push, then the 3D bridge) two panels, run
time against (a) the deck-displacement error and (b) the period error, log-log, one line per
integrator; dotted, the reference floor. Printed (markdown): the RK4 stability limit per
scene (from omega_max, and the largest stable rung measured), the sensitivity probe, and the
fastest integrator for each accuracy level per scene.
"""
import csv
import math
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.ticker  # noqa: E402

LEVELS = [1e-1, 1e-2, 1e-3, 1e-4]  # relative deck-displacement error
PERIOD_LEVELS = [1e-2, 1e-4, 1e-6]  # relative period error
STYLE = {"rk4": ("o-", "RK4 (dt ladder)"), "dopri5": ("s-", "DOPRI5 (rtol ladder)"),
         "sdirk3": ("^-", "SDIRK3 implicit (dt ladder)")}
SCENES = ("small", "3d", "table5")  # the order of the tables
PLOTTED = ("small", "3d")


def read(path):
    meta, rows = {}, []
    with open(path) as f:
        lines = f.read().splitlines()
    for line in lines:
        if line.startswith("#") and "scene=" in line:
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


def label(n, scene):
    return "3D" if scene == "3d" else str(n)


def fastest(rows, key, level):
    good = [r for r in rows if r["ok"] and r[key] <= level]
    if not good:
        return "–"
    best = min(good, key=lambda r: r["wall_s"])
    return f"{best['method']} {best['parameter']:g} ({best['wall_s'] * 1e3:.3g} ms)"


def main():
    meta, rows = read(sys.argv[1])
    out = sys.argv[2]
    scenes = sorted({(r["n"], r["scene"]) for r in rows if r["scene"] in PLOTTED},
                    key=lambda k: (PLOTTED.index(k[1]), k[0]))
    per_row = 2  # scenes per figure row, two panels each
    nrows = (len(scenes) + per_row - 1) // per_row
    fig, axes = plt.subplots(nrows, 2 * per_row, figsize=(4 * 2 * per_row, 3.1 * nrows), squeeze=False)
    for i, (n, scene) in enumerate(scenes):
        m = meta.get((n, scene), {})
        sel = [r for r in rows if r["n"] == n and r["scene"] == scene]
        for j, (key, what, floor) in enumerate((("disp_error", "deck displacement error", "ref_floor_disp"),
                                                 ("period_error", "period error", "ref_floor_period"))):
            ax = axes[i // per_row][2 * (i % per_row) + j]
            for method, (fmt, name) in STYLE.items():
                pts = sorted((r["wall_s"], r[key]) for r in sel if r["method"] == method and r["ok"])
                if pts:
                    ax.loglog([p[0] for p in pts], [max(p[1], 1e-12) for p in pts], fmt, label=name, ms=4)
            if m:
                ax.axhline(max(float(m[floor]), 1e-12), color="grey", lw=0.8, ls=":")
            failed = sum(1 for r in sel if r["method"] == "sdirk3" and r["status"].startswith("failed"))
            title = ("3D bridge (n = 2)" if scene == "3d" else f"n = {n}") + f": {what}"
            if m and j == 0:
                title += f"\nRK4 limit {float(m['rk4_limit']):.2g} s" + (", chaotic" if m.get("chaotic") == "1" else "")
            if j == 1 and failed:
                title += f"\nSDIRK3 failed at {failed} rung(s)"
            ax.set_title(title, fontsize=8)
            ax.set_xlabel("run time [s]", fontsize=8)
            ax.set_ylabel(f"{what} (rel.)", fontsize=8)
            ax.tick_params(labelsize=7)
            ax.xaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())  # they overlap on short spans
            ax.grid(True, which="major", lw=0.3)
    for ax in list(axes.flat)[2 * len(scenes):]:
        ax.axis("off")
    axes.flat[0].legend(fontsize=7)
    fig.suptitle("Work-precision, 1e-4 m push, 0.5 s (dotted: reference floor)", fontsize=10)
    fig.tight_layout(rect=(0, 0, 1, 0.985))
    fig.savefig(out, dpi=90)

    print("| bridge | engine | nodes | members | omega_max [rad/s] | RK4 limit 2 sqrt(2)/omega_max [s] "
          "| largest stable RK4 rung [s] | smallest unstable rung [s] | sensitivity (1e-10 push change) |")
    print("|---|---|---|---|---|---|---|---|---|")
    for n, scene in scenes:
        m = meta[(n, scene)]
        rk = [r for r in rows if r["n"] == n and r["scene"] == scene and r["method"] == "rk4"]
        stable = [r["parameter"] for r in rk if r["ok"]]
        unstable = [r["parameter"] for r in rk if r["status"] == "unstable"]
        print(f"| {label(n, scene)} | {m['engine']} | {m['nodes']} | {m['members']} | {float(m['omega_max']):.4g} "
              f"| {float(m['rk4_limit']):.3g} | {max(stable) if stable else '–'} | {min(unstable) if unstable else '–'} "
              f"| {float(m['sensitivity']):.1e} |")
    print()
    for scene in SCENES:
        sn = sorted({r["n"] for r in rows if r["scene"] == scene})
        if not sn:
            continue
        print(f"Fastest run per accuracy level, scene `{scene}` (method, dt or rtol, run time):\n")
        head = " | ".join([f"disp <= {l:g}" for l in LEVELS] + [f"period <= {l:g}" for l in PERIOD_LEVELS])
        print(f"| n | ref dt [s] | ref floor (disp / period) | {head} |")
        print("|---" * (3 + len(LEVELS) + len(PERIOD_LEVELS)) + "|")
        for n in sn:
            sel = [r for r in rows if r["n"] == n and r["scene"] == scene]
            m = meta[(n, scene)]
            cells = [fastest(sel, "disp_error", l) for l in LEVELS] + [fastest(sel, "period_error", l) for l in PERIOD_LEVELS]
            print(f"| {label(n, scene)} | {float(m['ref_dt']):.3g} | {float(m['ref_floor_disp']):.1e} / "
                  f"{float(m['ref_floor_period']):.1e} | " + " | ".join(cells) + " |")
        print()
    failed = [r for r in rows if r["status"] not in ("ok", "unstable")]
    if failed:
        print("Failed runs (the full status is in the CSV):\n")
        print("| bridge | scene | method | parameter | run time until it stopped [s] | why |")
        print("|---|---|---|---|---|---|")
        for r in failed:
            print(f"| {label(r['n'], r['scene'])} | {r['scene']} | {r['method']} | {r['parameter']:g} | "
                  f"{r['wall_s']:.3g} | {why(r['status'])} |")
        print()


def why(status):
    """The failure in a few words, with the time it happened."""
    m = re.search(r"from t = (\S+) s \(dt = (\S+) s\)", status)
    if "Newton" in status and m:
        return f"Newton failed at t = {float(m[1]):.3g} s (step halved down to {float(m[2]):.3g} s)"
    m = re.search(r"step (\S+) s at t = (\S+) s fell below", status)
    if m:
        return f"step fell to {float(m[1]):.1g} s at t = {float(m[2]):.3g} s"
    return status[:100]


if __name__ == "__main__":
    main()
