#!/usr/bin/env python3
"""The whole `tbridge simulate` process against its kernel: what a user's run costs per step.

Usage: bench/simulate_process.py [--build build] [--repeats 3] [--memory-steps 10000000]
                                 [--per-member-step-only]

1. Per member-step on the paper's planar bridge (configs/paper_n1.json at n = 6, 8, 10; RK4,
   stabilisation on, no damping, the longest bar 1 mm down, dt = 1e-7 s so every step costs the
   same): whole-process wall time of a long run minus a short one, over their step difference,
   with the monitor and summary on (the deck frequency included); beside bench_step's bare
   stabilised step and its two yardsticks, hand-written loops (plain, and structure-of-arrays),
   timed in the same script run.
2. The MOTES prism and D-bar (configs/motes_*.json, 5000 RK4 steps, as shipped and with
   nothing recorded): in-run time per step (summary.json run.wall_s / run.steps, best run)
   against bench_motes's bare loop (best of its runs, interleaved with them), and the whole
   process (best of the same runs) against the in-run time.
3. Memory: the prism for 1e6 and 1e7 steps with history every 100 steps; peak RSS of each.
4. Start-up: a one-step simulate of the prism against `tbridge --version` and /bin/true.

Wall time is the best of `repeats` fresh processes; peak memory is tbridge's largest resident
set as GNU time reports it (`/usr/bin/time -f %M`, Debian package "time") in one more run.
Prints Markdown.
"""
import argparse
import json
import os
import re
import subprocess
import sys
import tempfile
import time

SOURCE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def run(cmd, repeats=1, rss=True):
    """Best wall time [s] of `repeats` runs of cmd, and its peak RSS [MiB] from one more run
    under GNU time (kept out of the timed runs: it adds milliseconds of its own; 0 when rss is
    off)."""
    best = float("inf")
    for _ in range(repeats):
        start = time.perf_counter()
        proc = subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        wall = time.perf_counter() - start
        if proc.returncode != 0:
            sys.exit(f"{' '.join(cmd)} failed ({proc.returncode}): {proc.stderr[-2000:]}")
        best = min(best, wall)
    if not rss:
        return best, 0.0
    with tempfile.NamedTemporaryFile("r") as report:
        subprocess.run(["/usr/bin/time", "-o", report.name, "-f", "%M"] + cmd, stdout=subprocess.DEVNULL,
                       stderr=subprocess.DEVNULL, check=True)
        rss = int(report.read().split()[-1]) / 1024.0  # %M is in KiB
    return best, rss


def write(path, config):
    with open(path, "w") as f:
        json.dump(config, f)
    return path


def simulate(args, config_path, outdir, repeats, rss=True):
    wall, rss = run([args.tbridge, "simulate", config_path, "-o", outdir, "-q"], repeats, rss)
    with open(os.path.join(outdir, "summary.json")) as f:
        return wall, rss, json.load(f)


def paper_scene(n, steps):
    with open(os.path.join(SOURCE, "configs", "paper_n1.json")) as f:
        config = json.load(f)
    config["bridge"]["n"] = n
    dt = 1e-7
    config["dynamics"] = {"integrator": "rk4", "dt": dt, "duration": steps * dt, "deck_inertia": False,
                          "string_mass": "bars", "stabilisation": {"enabled": True},
                          "perturbation": {"bar_class": 1, "delta": 1e-3}, "record": {"csv": False}}
    return config


def bench_step_rows(args, ns):
    out = subprocess.run([args.bench_step, str(max(ns)), str(min(ns))], capture_output=True, text=True,
                         check=True).stdout
    rows = {}
    for line in out.splitlines():
        f = line.split()
        if len(f) == 10 and f[0].isdigit():
            rows[int(f[0])] = {"members": int(f[1]), "stabilised": float(f[5]), "yardstick": float(f[6]),
                               "soa": float(f[7])}
    return rows


def per_member_step(args, work):
    ns = (6, 8, 10)
    print("### `tbridge simulate` per member-step against the bare step\n")
    print("| n | members | steps (long - short) | simulate [ns/member-step] | bare step | yardstick "
          "| soa yardstick | simulate / bare | bare / yardstick | simulate / soa |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    rows = []
    for n in ns:
        long_ = int(2e7 / (4 * 2 ** n))  # ~0.5 s of stepping at 25 ns a member-step (~4 * 2^n members)
        short = long_ // 10
        walls = []
        for steps in (short, long_):
            path = write(os.path.join(work, f"paper_{n}_{steps}.json"), paper_scene(n, steps))
            wall, _, summary = simulate(args, path, os.path.join(work, f"out_{n}_{steps}"), args.repeats)
            walls.append((wall, summary["run"]["steps"]))
        members = summary["model"]["bars"] + summary["model"]["strings"] if "model" in summary else None
        rows.append((n, walls, members))
    bare = bench_step_rows(args, ns)  # after the processes, in the same script run
    for n, walls, members in rows:
        b = bare[n]
        members = members or b["members"]
        ns_sim = 1e9 * (walls[1][0] - walls[0][0]) / ((walls[1][1] - walls[0][1]) * members)
        print(f"| {n} | {members} | {walls[1][1] - walls[0][1]} | {ns_sim:.1f} | {b['stabilised']:.1f} | "
              f"{b['yardstick']:.1f} | {b['soa']:.1f} | {ns_sim / b['stabilised']:.2f} | "
              f"{b['stabilised'] / b['yardstick']:.2f} | {ns_sim / b['soa']:.2f} |")
    print()


def bench_motes(args):
    out = subprocess.run([args.bench_motes], capture_output=True, text=True, check=True).stdout
    return {m.group(1): float(m.group(2)) for m in re.finditer(r"^(\S+)\s.*?: ([0-9.]+) us/step", out, re.M)}


def motes(args, work):
    """The shipped configs (history of every node every 10 steps to history.csv), and the same
    with nothing recorded; bench_motes is run between them and its best taken."""
    print("### MOTES scenes: in-run and whole process against bench_motes\n")
    print("| scene | recorded | steps | bench_motes [us/step] | in-run [us/step] | in-run / bare "
          "| whole process [ms] | in-run [ms] | whole / in-run |")
    print("|---|---|---|---|---|---|---|---|---|")
    bare = {}
    for name, key in (("prism", "prism"), ("dbar", "d-bar")):
        with open(os.path.join(SOURCE, "configs", f"motes_{name}.json")) as f:
            config = json.load(f)
        shipped = os.path.join(SOURCE, "configs", f"motes_{name}.json")
        config["dynamics"]["record"] = {"csv": False}
        quiet = write(os.path.join(work, f"motes_{name}_norecord.json"), config)
        for label, path in (("every node, every 10 steps (shipped)", shipped), ("nothing", quiet)):
            outdir = os.path.join(work, f"motes_{name}")
            # The best whole process and the best in-run time (the summary's) over the same
            # runs, each run interleaved with bench_motes.
            wall = best_in_run = float("inf")
            for _ in range(2 * args.repeats + 1):
                w, _, summary = simulate(args, path, outdir, 1, rss=False)
                wall = min(wall, w)
                best_in_run = min(best_in_run, summary["run"]["wall_s"])
                for k, v in bench_motes(args).items():
                    bare[k] = min(bare.get(k, float("inf")), v)
            steps = summary["run"]["steps"]
            us = 1e6 * best_in_run / steps
            print(f"| {key} | {label} | {steps} | {bare[key]:.2f} | {us:.2f} | {us / bare[key]:.2f} | "
                  f"{1e3 * wall:.1f} | {1e3 * best_in_run:.1f} | {wall / best_in_run:.2f} |")
    print()


def memory(args, work):
    with open(os.path.join(SOURCE, "configs", "motes_prism.json")) as f:
        base = json.load(f)
    print("### Memory against run length (MOTES prism, history of 24 nodes every 100 steps)\n")
    print("| steps | wall [s] | history.csv [MB] | peak RSS [MiB] |")
    print("|---|---|---|---|")
    for steps in (args.memory_steps // 10, args.memory_steps):
        config = json.loads(json.dumps(base))
        config["dynamics"]["duration"] = steps * config["dynamics"]["dt"]
        config["dynamics"]["record"]["every"] = 100
        path = write(os.path.join(work, f"prism_{steps}.json"), config)
        outdir = os.path.join(work, f"prism_{steps}")
        wall, rss, summary = simulate(args, path, outdir, 1)
        size = os.path.getsize(os.path.join(outdir, "history.csv")) / 1e6
        print(f"| {summary['run']['steps']} | {wall:.1f} | {size:.0f} | {rss:.1f} |")
        os.remove(os.path.join(outdir, "history.csv"))
    print()


def start_up(args, work):
    with open(os.path.join(SOURCE, "configs", "motes_prism.json")) as f:
        config = json.load(f)
    config["dynamics"]["duration"] = config["dynamics"]["dt"]
    config["dynamics"]["record"] = {"csv": False}
    path = write(os.path.join(work, "one_step.json"), config)
    print("### Start-up (best of 20 processes)\n")
    print("| process | wall [ms] | peak RSS [MiB] |")
    print("|---|---|---|")
    for label, cmd in (("`tbridge simulate` of the prism, one step", [args.tbridge, "simulate", path, "-o",
                                                                     os.path.join(work, "one"), "-q"]),
                       ("`tbridge --version`", [args.tbridge, "--version"]), ("`/bin/true`", ["/bin/true"])):
        wall, rss = run(cmd, 20)
        print(f"| {label} | {1e3 * wall:.1f} | {rss:.1f} |")
    print()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--build", default=os.path.join(SOURCE, "build"))
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--memory-steps", type=int, default=10_000_000)
    parser.add_argument("--per-member-step-only", action="store_true",
                        help="only part 1, the cost per member-step against the yardsticks")
    args = parser.parse_args()
    args.tbridge = os.path.join(args.build, "tbridge")
    args.bench_step = os.path.join(args.build, "bench", "bench_step")
    args.bench_motes = os.path.join(args.build, "bench", "bench_motes")
    print(f"Machine: {' '.join(os.uname())}; {os.cpu_count()} cores\n")
    with tempfile.TemporaryDirectory() as work:
        per_member_step(args, work)
        if args.per_member_step_only:
            return
        motes(args, work)
        start_up(args, work)
        memory(args, work)


if __name__ == "__main__":
    main()
