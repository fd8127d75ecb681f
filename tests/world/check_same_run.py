#!/usr/bin/env python3
"""The same world, seed and firmware give byte-identical trajectories.csv
and objects.csv, on one thread or several. check_same_run.py SIM ELF WORLD
OUT runs it twice: the robots on one thread, then shared among two."""
import filecmp
import subprocess
import sys

sim, elf, world, out = sys.argv[1:5]
for run, threads in (("first", "1"), ("second", "2")):
    done = subprocess.run([sim, "--world", world, "--out", f"{out}/{run}", "--threads", threads,
                           "--time", "4", "-q", elf],
                          capture_output=True, text=True, timeout=240)
    if done.returncode != 0:
        sys.exit(f"openswarm-sim failed ({done.returncode}):\n{done.stderr}")
same = 0
for name in ("trajectories.csv", "objects.csv"):
    if filecmp.cmp(f"{out}/first/{name}", f"{out}/second/{name}", shallow=False):
        same += 1
    else:
        print(f"FAIL {name} differs between the runs on one thread and on two")
print(f"{same} passed, {2 - same} failed")
sys.exit(0 if same == 2 else 1)
