#!/usr/bin/env python3
"""Times renders that take turns, for same-run comparisons on a noisy machine.

Each round runs every variant once (`rtvk bench ... --repeat 1`, whose warm-up render is not
timed), in the order given, so a slow minute of the machine slows every variant alike. Prints each
variant's times, median and minimum, and the median ratio of each to the first.

    scripts/bench-alternate.py --rounds 7 \\
        --variant "old fast=/tmp/old/rtvk --precision fast" \\
        --variant "fast=build/ci/rtvk --precision fast" \\
        --variant "reference=build/ci/rtvk --precision reference" \\
        -- bench --scene book-final --width 1200 --aspect 16:9 --spp 10 --depth 20 \\
           --backend cpu --threads 2
"""
import argparse
import re
import resource
import shlex
import statistics
import subprocess
import sys


def seconds(command, cpu):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    out = subprocess.run(command, capture_output=True, text=True, check=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if cpu:  # the process's processor time, warm-up and set-up included
        return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    times = re.findall(r" in ([0-9.]+) s", out.stdout + out.stderr)
    if not times:
        sys.exit("no time in the output of: " + " ".join(command))
    return float(times[-1])


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--rounds", type=int, default=5)
    p.add_argument("--cpu", action="store_true",
                   help="time each process's processor time (user + system, its warm-up and "
                        "set-up included) instead of the render's wall time it prints")
    p.add_argument("--variant", action="append", required=True,
                   help="NAME=EXECUTABLE [ARGS...]: its own arguments follow the common ones")
    p.add_argument("common", nargs=argparse.REMAINDER, help="-- then the common arguments")
    a = p.parse_args()
    common = a.common[1:] if a.common[:1] == ["--"] else a.common
    variants = []
    for v in a.variant:
        name, _, command = v.partition("=")
        words = shlex.split(command)
        variants.append((name, words[:1] + common + words[1:] + ["--repeat", "1"]))
    times = {name: [] for name, _ in variants}
    for _ in range(a.rounds):
        for name, command in variants:
            times[name].append(seconds(command, a.cpu))
    first = statistics.median(times[variants[0][0]])
    for name, _ in variants:
        t = times[name]
        m = statistics.median(t)
        print(f"{name}: median {m:.3f} s, min {min(t):.3f} s, {first / m:.2f}x the first's "
              f"speed; runs {', '.join(f'{x:.3f}' for x in t)}")


if __name__ == "__main__":
    main()
