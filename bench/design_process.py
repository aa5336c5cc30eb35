#!/usr/bin/env python3
"""Whole-process `tbridge design` time and peak memory against n: the user's path (start, read
the config, design, write the JSON), on the paper's model and switches (no self-weight in the
design, one load case, no dynamic check).

Usage: bench/design_process.py [--tbridge build/tbridge] [--max-n 16] [--repeats 3] [--max-n-3d 8]
       bench/design_process.py --verified [--max-n 6] [--planes 2]

--verified measures instead the engineering default (configs/default.json's settings at each n):
every load case, self-weight, the static and dynamic checks and the resizing loop; with
--planes 2, on the 3D bridge. Its table gives the wall time by part (the sizing, the static
check, the dynamic runs) that `tbridge design --progress` prints, of the fastest repeat.

Each run is a fresh process; wall time is the best of `repeats`, peak memory the largest
resident set of tbridge as GNU time reports it (`/usr/bin/time -f %M`, Debian package "time").
Not Python's own wait4: Linux carries the parent's high-water mark into a spawned child. Prints Markdown tables: planar p = 1 bridges
n = 1..max_n, the 3D bridge n = 1..max_n_3d, and the cost per member with the process start-up
(the n = 1 design) subtracted, with its spread over n = 8..max_n.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile
import time


def paper_config(n, planes):
    """The paper's bridge (SPEC §1) at complexity n; planes = 2 is its 3D bridge (Sect. 7.3)."""
    design = {"yield_safety_factor": 10, "buckling_safety_factor": 1, "deck_string_min_radius": 0.01,
              "gravity": 9.81, "solver": "auto", "self_weight": False, "bar_resistance": "euler"}
    bridge = {"n": n, "p": 1, "beta_deg": 10.0 if planes == 1 else 20.0, "span": 12.0, "payload": 12000.0,
              "deck_width": 1.5, "planes": planes}
    if planes == 2:
        design["transverse_string_min_radius"] = 0.005
    return {"bridge": bridge, "material": {"density": 7862, "yield_stress": 6.9e8, "youngs_modulus": 2.06e11},
            "design": design, "loads": {"cases": ["paper"]}}


def run_once(tbridge, config_path, out_path, parts=False):
    """Wall time [s], peak RSS [MB] and, with `parts`, the time by part that `--progress` prints
    last on stderr (an older tbridge that does not print it: None)."""
    with tempfile.NamedTemporaryFile("r") as report:
        start = time.perf_counter()
        proc = subprocess.run(["/usr/bin/time", "-o", report.name, "-f", "%M", tbridge, "design", config_path,
                               "-o", out_path, "-q"] + (["--progress"] if parts else []),
                              stdout=subprocess.DEVNULL, stderr=subprocess.PIPE if parts else subprocess.DEVNULL)
        wall = time.perf_counter() - start
        # 1 is a design written with a FAIL or INCOMPLETE verdict, which the table reports.
        if proc.returncode not in (0, 1):
            sys.exit(f"tbridge design {config_path} failed with exit code {proc.returncode}")
        by_part = None
        if parts:
            lines = [line for line in proc.stderr.decode(errors="replace").splitlines()
                     if line.startswith("time by part [s]: ")]
            if lines:
                # "time by part [s]: first design 0.01, sizing 3.7, ... (6 designs)"
                fields = lines[-1][len("time by part [s]: "):].split(" (")[0].split(", ")
                by_part = {f.rsplit(" ", 1)[0]: float(f.rsplit(" ", 1)[1]) for f in fields}
        return wall, int(report.read().split()[-1]) / 1024.0, by_part  # %M is in KiB


def measure(tbridge, n, planes, repeats, workdir, verified=False):
    config_path = os.path.join(workdir, f"config_{planes}_{n}.json")
    out_path = os.path.join(workdir, f"design_{planes}_{n}.json")
    with open(config_path, "w") as f:
        json.dump({"bridge": {"n": n, "planes": planes}} if verified else paper_config(n, planes), f)
    runs = [run_once(tbridge, config_path, out_path, parts=verified) for _ in range(repeats)]
    best = min(runs, key=lambda r: r[0])
    with open(out_path) as f:
        d = json.load(f)
    members = d["topology"]["bars"] + d["topology"]["strings"]
    return {"n": n, "members": members, "wall_s": min(r[0] for r in runs), "rss_mb": max(r[1] for r in runs),
            "solver": f'{d["solver"]["name"]} ({d["solver"]["problem"]})', "states": d["self_stress_states"],
            "mass": d["mass"]["total"], "bytes": os.path.getsize(out_path), "verdict": d["verdict"]["summary"],
            "designs": d["resizing"]["iterations"], "dynamic": dynamic_steps(d["dynamic_check"]),
            "structure": d["mass"]["structure"], "parts": best[2]}


def dynamic_steps(check):
    """Method and steps per dynamic run ("paper_travelling rk4 2500"; a modal run's steps are its
    samples), or why a run was not done."""
    return ", ".join(f'{r["name"]} ' + (f'{r["integrator"].split(" ")[0]} {r["steps"]}' if r["done"] else r["note"])
                     for r in check["runs"])


def verified_table(args, workdir):
    rows = [measure(args.tbridge, n, args.planes, args.repeats, workdir, verified=True)
            for n in range(1, args.max_n + 1)]
    print(f"Machine: {' '.join(os.uname())}; {os.cpu_count()} cores\n")
    print("| n | members | designs | structure [kg] | dynamic check (method, steps) | wall [s] | "
          "sizing / static / dynamic [s] | peak RSS [MB] | verdict |")
    print("|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        p = r["parts"]
        parts = f'{p["sizing"]:.2f} / {p["static check"]:.2f} / {p["dynamic check"]:.2f}' if p else "-"
        print(f'| {r["n"]} | {r["members"]} | {r["designs"]} | {r["structure"]:.1f} | {r["dynamic"]} | '
              f'{r["wall_s"]:.2f} | {parts} | {r["rss_mb"]:.1f} | {r["verdict"][:60]} |')


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--tbridge", default="build/tbridge")
    parser.add_argument("--max-n", type=int, default=16)
    parser.add_argument("--max-n-3d", type=int, default=8)
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--verified", action="store_true")
    parser.add_argument("--planes", type=int, choices=(1, 2), default=1, help="with --verified: 2 for the 3D bridge")
    args = parser.parse_args()
    if args.verified:
        with tempfile.TemporaryDirectory() as workdir:
            verified_table(args, workdir)
        return
    with tempfile.TemporaryDirectory() as workdir:
        planar = [measure(args.tbridge, n, 1, args.repeats, workdir) for n in range(1, args.max_n + 1)]
        spatial = [measure(args.tbridge, n, 2, args.repeats, workdir) for n in range(1, args.max_n_3d + 1)]
    print(f"Machine: {' '.join(os.uname())}; {os.cpu_count()} cores\n")
    for title, rows in (("planar, p = 1", planar), ("3D, two planes", spatial)):
        print(f"### {title}\n")
        print("| n | members | solver | self-stresses | total mass [kg] | wall [s] | peak RSS [MB] | JSON [MB] |")
        print("|---|---|---|---|---|---|---|---|")
        for r in rows:
            print(f'| {r["n"]} | {r["members"]} | {r["solver"]} | {r["states"]} | {r["mass"]:.3f} | '
                  f'{r["wall_s"]:.3f} | {r["rss_mb"]:.1f} | {r["bytes"] / 1e6:.2f} |')
        print()
    base = planar[0]
    print("### Cost per member above the start-up (planar; start-up = the n = 1 process)\n")
    print("| n | (wall - start-up) / members [us] | (RSS - start-up RSS) / members [bytes] |")
    print("|---|---|---|")
    per_member = []
    for r in planar:
        if r["n"] < 8:
            continue
        t = (r["wall_s"] - base["wall_s"]) / r["members"] * 1e6
        m = (r["rss_mb"] - base["rss_mb"]) * 1024 * 1024 / r["members"]
        per_member.append(t)
        print(f'| {r["n"]} | {t:.2f} | {m:.0f} |')
    if per_member:
        print(f"\nSpread of the time per member over n = 8..{args.max_n}: "
              f"max / min = {max(per_member) / min(per_member):.2f} (target: within 2x)")


if __name__ == "__main__":
    main()
