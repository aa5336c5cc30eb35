#!/usr/bin/env python3
"""What `--vtk` costs a `tbridge simulate` run: the whole process with and without the ParaView
series, best of `repeats` fresh processes each, interleaved so that both see the same machine.

Usage: bench/vtk_process.py [--tbridge build/tbridge] [--repeats 5]

The scenes: the paper's n = 3 travelling-load run as shipped (configs/paper_t5_n3_d1.json) and
the MOTES prism (configs/motes_prism.json), each recording as its config says. Prints Markdown:
the runs' wall times, the samples written and the ratio with / without (the target is at most
1.2).
"""
import argparse
import json
import os
import platform
import subprocess
import tempfile
import time

SOURCE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENES = ["paper_t5_n3_d1.json", "motes_prism.json"]


def run(tbridge, config, out, vtk):
    args = [tbridge, "simulate", config, "-q", "-o", out] + (["--vtk", vtk] if vtk else [])
    start = time.perf_counter()
    subprocess.run(args, check=True, capture_output=True)
    return time.perf_counter() - start


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--tbridge", default=os.path.join(SOURCE, "build", "tbridge"))
    parser.add_argument("--repeats", type=int, default=5)
    args = parser.parse_args()
    print("Machine: %s %s; %d cores" % (platform.platform(), platform.processor() or "", os.cpu_count()))
    print()
    print("| scene | steps | VTK samples | without --vtk [s] | with --vtk [s] | ratio |")
    print("|---|---|---|---|---|---|")
    for scene in SCENES:
        config = os.path.join(SOURCE, "configs", scene)
        with tempfile.TemporaryDirectory() as tmp:
            out, vtk = os.path.join(tmp, "out"), os.path.join(tmp, "vtk")
            plain, with_vtk = [], []
            for _ in range(args.repeats):
                plain.append(run(args.tbridge, config, out, None))
                with_vtk.append(run(args.tbridge, config, out, vtk))
            with open(os.path.join(out, "summary.json")) as f:
                steps = json.load(f)["run"]["steps"]
            with open(os.path.join(vtk, "run.xdmf")) as f:
                samples = f.read().count('<Grid Name="sample ')
        a, b = min(plain), min(with_vtk)
        print("| %s | %d | %d | %.3f | %.3f | %.3f |" % (scene, steps, samples, a, b, b / a))


if __name__ == "__main__":
    main()
