#!/usr/bin/env python3
"""A world with no robots runs to its end (world.no_robots).

check_no_robots.py SIM WORLD OUT: docs/world.md allows a world without
robots; openswarm-sim spun forever on one at 100% CPU (with no robot it
had no clock, and the physics step was 0 cycles long). Checks:
  the run ends with status 0;
  trajectories.csv has its header and no robot;
  objects.csv has the object every sample_period_s (0.1 s) up to the
  world's duration_s (0.3 s): the world ran to its end.
The test's ctest TIMEOUT bounds a run that spins.
"""
import csv
import subprocess
import sys

from behaviour import Checks

sim, world, out = sys.argv[1:4]
done = subprocess.run([sim, "--world", world, "--out", out, "-q"], capture_output=True, text=True)
checks = Checks()
checks.expect(done.returncode == 0, f"the run ends with status 0 ({done.returncode}): {done.stderr.strip()}")
if done.returncode == 0:
    with open(f"{out}/trajectories.csv") as f:
        rows = list(csv.reader(f))
    checks.expect(len(rows) == 1 and "robot" in rows[0], f"trajectories.csv: a header, no robot ({len(rows)} rows)")
    with open(f"{out}/objects.csv") as f:
        times = [round(float(row["time_s"]), 3) for row in csv.DictReader(f)]
    checks.expect(times == [0.0, 0.1, 0.2, 0.3], f"objects.csv sampled at 0, 0.1, 0.2 and 0.3 s: {times}")
checks.finish()
