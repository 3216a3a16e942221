#!/usr/bin/env python3
"""A/B of ncverify builds on one workload: runs each binary in turn, 1 and 2 threads,
REPS rounds, and prints the median of each `run --timings` phase. Alternating in one
session is the only fair comparison on a shared machine.

  bench/compare_binaries.py REPS WORKPIECE NOMINAL BINARY...
  e.g. bench/compare_binaries.py 5 samples/large/core_finishing.stl \
           samples/large/core_nominal.stl old/ncverify build-bench/ncverify
"""
import json
import os
import statistics
import subprocess
import sys
import tempfile

if len(sys.argv) < 5:
    sys.exit(__doc__)
reps, workpiece, nominal, binaries = int(sys.argv[1]), sys.argv[2], sys.argv[3], sys.argv[4:]
samples = None
times = {}
with tempfile.TemporaryDirectory() as tmp:
    timings = os.path.join(tmp, "timings.json")
    for _ in range(reps):
        for binary in binaries:
            for threads in (1, 2):
                subprocess.run([binary, "--threads", str(threads), "-q", "run", workpiece, nominal,
                                "-d", os.path.join(tmp, "out"), "--timings", timings],
                               stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=False)
                with open(timings) as f:
                    t = json.load(f)
                samples = t["samples"]
                for phase, seconds in t["phases"].items():
                    times.setdefault((binary, threads, phase), []).append(seconds)
phases = sorted({phase for (_, _, phase) in times})
print(f"{'binary':<40}{'threads':>8}" + "".join(f"{p:>11}" for p in phases) + f"{'M samp/s':>10}")
for binary in binaries:
    for threads in (1, 2):
        medians = {p: statistics.median(times[(binary, threads, p)]) for p in phases}
        print(f"{binary[-40:]:<40}{threads:>8}" + "".join(f"{medians[p]:>11.3f}" for p in phases)
              + f"{samples / medians['distance'] / 1e6:>10.2f}")
print(f"(medians of {reps}; load average {os.getloadavg()[0]:.2f} at the end)")
