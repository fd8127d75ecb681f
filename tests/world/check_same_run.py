#!/usr/bin/env python3
"""The same world, seed and firmware give byte-identical trajectories.csv
and objects.csv, on one thread or several. check_same_run.py SIM ELF WORLD
OUT [SIMULATOR OPTIONS] runs it twice: the robots on one thread, then
shared among two. With --faults among the options, each run's fault log
(faults.log) must be the same too, and name a fault."""
import filecmp
import os
import subprocess
import sys

sim, elf, world, out = sys.argv[1:5]
extra = sys.argv[5:]
names = ["trajectories.csv", "objects.csv"]
if "--faults" in extra:
    names.append("faults.log")
for run, threads in (("first", "1"), ("second", "2")):
    os.makedirs(f"{out}/{run}", exist_ok=True)
    log = ["--fault-log", f"{out}/{run}/faults.log"] if "--faults" in extra else []
    done = subprocess.run([sim, "--world", world, "--out", f"{out}/{run}", "--threads", threads,
                           "--time", "4", "-q", *extra, *log, elf],
                          capture_output=True, text=True, timeout=240)
    if done.returncode != 0:
        sys.exit(f"openswarm-sim failed ({done.returncode}):\n{done.stderr}")
if "--faults" in extra and os.path.getsize(f"{out}/first/faults.log") == 0:
    sys.exit("FAIL the faults asked for left the log empty")
same = 0
for name in names:
    if filecmp.cmp(f"{out}/first/{name}", f"{out}/second/{name}", shallow=False):
        same += 1
    else:
        print(f"FAIL {name} differs between the runs on one thread and on two")
print(f"{same} passed, {len(names) - same} failed")
sys.exit(0 if same == len(names) else 1)
