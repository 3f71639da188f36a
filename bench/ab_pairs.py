#!/usr/bin/env python3
"""Time two commands as whole processes, in alternating pairs, with Python's standard library only.

    python3 bench/ab_pairs.py [-n PAIRS] [--warmup RUNS] [--timeout SECONDS] --vs 'COMMAND_B' -- COMMAND_A [ARG ...]
    python3 bench/ab_pairs.py [-n RUNS] [--warmup RUNS] [--timeout SECONDS] -- COMMAND [ARG ...]

Each run is one process started without a shell (COMMAND_B is split as a shell splits words),
timed from its start to its exit: wall seconds from a monotonic clock, user and system seconds
from the operating system's accounting of the reaped child (its children included). With --vs,
A and B run in turn, A B A B ..., after WARMUP runs of each that are not counted, and the ratio
A/B is taken pair by pair, so that a drift of the machine's speed during the call moves both
sides of a pair alike. Printed: min, median and max of every figure and of the pairs' ratios;
quote the median. A variable for both commands goes before the program (X=1 python3 ...); one
for a single side is written `env X=1 COMMAND`. The commands' output is discarded. Exit status:
0 when every run was started (a command's own exit code is printed, not acted on), 2 for
unusable arguments, 3 when --timeout (one bound on the whole call) cut it short.

The documented timings of docs/performance.md are written in this form (they were taken as the
same kind of whole-process A/B pairs).
"""
import os
import resource
import shlex
import statistics
import subprocess
import sys
import time


def usage(message):
    sys.stderr.write(f"ab_pairs.py: {message}\n\n{__doc__}")
    sys.exit(2)


def parse(argv):
    opts = {"n": 5, "warmup": 1, "timeout": None, "vs": None}
    i = 0
    while i < len(argv) and argv[i] != "--":
        key = argv[i]
        if key not in ("-n", "--warmup", "--timeout", "--vs") or i + 1 >= len(argv):
            usage(f"unknown or incomplete option {key!r}")
        value = argv[i + 1]
        try:
            if key == "-n":
                opts["n"] = int(value)
            elif key == "--warmup":
                opts["warmup"] = int(value)
            elif key == "--timeout":
                opts["timeout"] = float(value)
            else:
                opts["vs"] = shlex.split(value)
        except ValueError:
            usage(f"{key} {value!r}: not a number")
        i += 2
    command = argv[i + 1:]
    if not command:
        usage("no command after --")
    if opts["n"] < 1 or opts["warmup"] < 0 or (opts["vs"] is not None and not opts["vs"]):
        usage("-n must be >= 1, --warmup >= 0 and --vs non-empty")
    return opts, command


def run_once(command, deadline):
    """(wall, user, system, exit code) of one run; None when the deadline killed it."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.monotonic()
    try:
        proc = subprocess.Popen(command, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                                stderr=subprocess.DEVNULL, start_new_session=True)
    except OSError as e:
        usage(f"cannot start {command[0]!r}: {e}")
    try:
        code = proc.wait(timeout=None if deadline is None else max(deadline - start, 0.001))
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, 9)
        proc.wait()
        return None
    wall = time.monotonic() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return wall, after.ru_utime - before.ru_utime, after.ru_stime - before.ru_stime, code


def spread(values):
    return f"{min(values):10.3f} {statistics.median(values):10.3f} {max(values):10.3f}"


def main():
    opts, a = parse(sys.argv[1:])
    b = opts["vs"]
    deadline = None if opts["timeout"] is None else time.monotonic() + opts["timeout"]
    sides = [("A", a)] + ([("B", b)] if b else [])
    for _ in range(opts["warmup"]):
        for _, cmd in sides:
            if run_once(cmd, deadline) is None:
                print("the time bound ended the warm-up")
                sys.exit(3)
    runs = {name: [] for name, _ in sides}
    cut = False
    for _ in range(opts["n"]):
        pair = [run_once(cmd, deadline) for _, cmd in sides]
        if any(r is None for r in pair):
            cut = True
            break
        for (name, _), r in zip(sides, pair):
            runs[name].append(r)
    print(f"{len(runs['A'])} {'pairs' if b else 'runs'} after {opts['warmup']} warm-up; min, median, max")
    for name, _ in sides:
        rs = runs[name]
        if not rs:
            continue
        print(f"{name} wall s   {spread([r[0] for r in rs])}")
        print(f"{name} cpu s    {spread([r[1] + r[2] for r in rs])}")
        codes = sorted({r[3] for r in rs})
        if codes != [0]:
            print(f"{name} exit codes {codes}")
    if b and runs["A"]:
        pairs = list(zip(runs["A"], runs["B"]))
        print(f"A/B wall   {spread([x[0] / y[0] for x, y in pairs])}")
        cpu = [(x[1] + x[2]) / (y[1] + y[2]) for x, y in pairs if y[1] + y[2] > 0]
        if cpu:
            print(f"A/B cpu    {spread(cpu)}")
    if cut:
        print("the time bound ended the call early")
        sys.exit(3)


if __name__ == "__main__":
    main()
