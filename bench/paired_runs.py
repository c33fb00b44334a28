#!/usr/bin/python3
"""Compare the single-thread throughput of two Pellicle builds by paired runs.

Each pair runs `pellicle bench` of build A on one core and of build B on the other at the
same moment (taskset), the cores swapped from one pair to the next; the figure is the
geometric mean over the pairs of B's throughput over A's. Whatever slows the machine during
a pair slows both runs, and the swapping cancels a difference between the two cores
(docs/theory/performance.md, "Measuring"). Runs should last a second or more: 100 steps for
the 2D linear cases, 30 for the others.

    bench/paired_runs.py OLD/bin/pellicle NEW/bin/pellicle --case two-disks --steps 100
    bench/paired_runs.py A B --case two-spheres-3d --case gas-box --steps 30 --pairs 8

Prints one line per case: each build's median throughput under pairing (M particle-steps/s),
the geometric mean of the ratios B/A and every pair's ratio. A build run against itself
gives ratios within a few per cent of 1; a difference smaller than their spread is noise.
"""

import argparse
import json
import os
import shutil
import statistics
import subprocess
import sys


def fail(message):
    print(f"paired_runs.py: error: {message}", file=sys.stderr)
    sys.exit(2)


def bench_command(binary, cpu, case, steps, points):
    command = ["taskset", "-c", str(cpu), binary, "bench", "--json", "--threads", "1",
               "--steps", str(steps), "--case", case]
    if points:
        command += ["--points", str(points)]
    return command


def throughput(result, binary, case):
    out, err, returncode = result
    if returncode != 0:
        fail(f"{binary}: bench of case '{case}' exited with {returncode}: {err.strip()}")
    try:
        return json.loads(out)[0]["particle_steps_per_second"] / 1e6
    except (ValueError, IndexError, KeyError):
        fail(f"{binary}: unexpected output of bench --json for case '{case}'")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("build_a", help="the pellicle binary to compare against")
    parser.add_argument("build_b", help="the pellicle binary compared")
    parser.add_argument("--case", action="append", required=True,
                        help="a pellicle bench case (repeat for several)")
    parser.add_argument("--steps", type=int, default=30, help="timed steps per run (30)")
    parser.add_argument("--points", type=int, default=0, help="points per case (bench's default)")
    parser.add_argument("--pairs", type=int, default=6, help="pairs per case, even (6)")
    args = parser.parse_args()
    for binary in (args.build_a, args.build_b):
        if not (os.path.isfile(binary) and os.access(binary, os.X_OK)):
            fail(f"{binary}: not an executable file")
    if shutil.which("taskset") is None:
        fail("taskset not found (Debian package util-linux)")
    if len(os.sched_getaffinity(0)) < 2:
        fail("paired runs need two cores")
    if args.pairs < 2 or args.pairs % 2:
        fail(f"--pairs must be even and at least 2, not {args.pairs}")
    if args.steps < 1:
        fail(f"--steps must be at least 1, not {args.steps}")
    cores = sorted(os.sched_getaffinity(0))[:2]
    for case in args.case:
        a_runs, b_runs, ratios = [], [], []
        for pair in range(args.pairs):
            core_a, core_b = (cores[0], cores[1]) if pair % 2 == 0 else (cores[1], cores[0])
            run_a = subprocess.Popen(bench_command(args.build_a, core_a, case, args.steps,
                                                   args.points),
                                     stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
            run_b = subprocess.Popen(bench_command(args.build_b, core_b, case, args.steps,
                                                   args.points),
                                     stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
            # Both runs end before either is checked, so a failure leaves no run behind.
            results = [(*run.communicate(), run.returncode) for run in (run_a, run_b)]
            a = throughput(results[0], args.build_a, case)
            b = throughput(results[1], args.build_b, case)
            a_runs.append(a)
            b_runs.append(b)
            ratios.append(b / a)
        print(f"{case:22s} A {statistics.median(a_runs):8.3f}  B {statistics.median(b_runs):8.3f}"
              f"  B/A {statistics.geometric_mean(ratios):.4f}"
              f"  pairs {' '.join(f'{r:.3f}' for r in ratios)}", flush=True)


if __name__ == "__main__":
    main()
