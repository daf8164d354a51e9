#!/usr/bin/env python3
"""The 36,000-position four-bar sweep from Python into NumPy arrays (issue 30: <= 2 us per
position), beside the same sweep by the `gearkit kin` process (bench_kin_process's case:
examples/mechanisms/four_bar.yaml, --sweep 0:359.99:0.01 --format csv to /dev/null).

usage: PYTHONPATH=build/python /usr/bin/python3 bench/python_sweep.py [--exe build/bin/gearkit] [--repeats 5]

Prints the median per position of each, interleaved so that both see the same machine load.
The Python figure is the sweep call alone (the module already imported, the file read): the
solve, velocities, accelerations and the three outputs of every position written into the
arrays. Not part of ctest: tests never time things.
"""

import argparse
import os
import statistics
import subprocess
import sys
import time

import gearkit

HERE = os.path.dirname(os.path.abspath(__file__))
FOUR_BAR = os.path.join(HERE, "..", "examples", "mechanisms", "four_bar.yaml")
POSITIONS = 36000
DEG = 3.141592653589793 / 180


def python_sweep(m):
    t = time.perf_counter()
    s = m.sweep(0.0, 359.99 * DEG, 0.01 * DEG)
    elapsed = time.perf_counter() - t
    assert len(s) == POSITIONS and s.complete, (len(s), s.message)
    return elapsed


def python_sweep_with_dataframe(m):
    t = time.perf_counter()
    frame = m.sweep(0.0, 359.99 * DEG, 0.01 * DEG).to_dataframe()
    elapsed = time.perf_counter() - t
    assert len(frame) == POSITIONS
    return elapsed


def cli_sweep(exe):
    with open(os.devnull, "w") as null:
        t = time.perf_counter()
        subprocess.run([exe, "kin", FOUR_BAR, "--sweep", "0:359.99:0.01", "--format", "csv"], stdout=null, stderr=null, check=True)
        return time.perf_counter() - t


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--exe", default=os.path.join(HERE, "..", "build", "bin", "gearkit"))
    p.add_argument("--repeats", type=int, default=5)
    a = p.parse_args()
    m = gearkit.Mechanism(FOUR_BAR)
    python_sweep(m)  # warm-up: page in the libraries
    times = {"python sweep -> NumPy": [], "python sweep -> DataFrame": [], "gearkit kin --format csv (process)": []}
    for _ in range(a.repeats):
        times["python sweep -> NumPy"].append(python_sweep(m))
        times["python sweep -> DataFrame"].append(python_sweep_with_dataframe(m))
        times["gearkit kin --format csv (process)"].append(cli_sweep(a.exe))
    load = open("/proc/loadavg").read().split()[:3]
    print(f"{POSITIONS} positions, {a.repeats} interleaved repeats, load {' '.join(load)}")
    for name, t in times.items():
        per = [x / POSITIONS * 1e6 for x in t]
        print(f"  {name:40s} median {statistics.median(per):.2f} us/position (min {min(per):.2f}, max {max(per):.2f})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
