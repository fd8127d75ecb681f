#!/usr/bin/env python3
"""--faults drift: a robot's clock runs fast or slow by what is asked.

check_drift_blink.py SIM ELF OUT: two robots run drift_blink.elf (LED on
for a Sys_Sleep(1000), off for another) for 21 s, robot 1 with --faults
drift:1=2 (its clock 2% fast), robot 0 undrifted. From the LED's edges in
the trace (world time) each robot's blink period is measured: robot 0's is
1000 ms, robot 1's 1000 / 1.02 = 980.4 ms (both within 0.05%); the fault
log has the drift, at 0 s, with its ppm.
"""
import csv
import os
import subprocess
import sys

sim, elf, out = sys.argv[1:4]
os.makedirs(out, exist_ok=True)
trace, log = os.path.join(out, "trace.csv"), os.path.join(out, "faults.log")
done = subprocess.run([sim, "--robots", "2", "--distance", "300", "--time", "21", "-q",
                       "--faults", "drift:1=2", "--fault-log", log, "--trace-csv", trace, elf],
                      capture_output=True, text=True, timeout=240)
if done.returncode != 0:
    sys.exit(f"openswarm-sim failed ({done.returncode}):\n{done.stdout}\n{done.stderr}")

edges = {0: [], 1: []}  # times the LED went on
with open(trace) as f:
    lit = {0: False, 1: False}
    for row in csv.DictReader(f):
        if row["device"] != "led":
            continue
        robot, on = int(row["robot"]), any(int(row[k]) for k in ("a", "b", "c"))
        if on and not lit[robot]:
            edges[robot].append(float(row["time_s"]))
        lit[robot] = on
failed = 0


def expect(ok, what):
    global failed
    print(("ok   " if ok else "FAIL ") + what)
    failed += not ok


for robot, want_ms in ((0, 1000.0), (1, 1000.0 / 1.02)):
    on = edges[robot]
    if len(on) < 9:
        expect(False, f"robot {robot}: {len(on)} LED edges, too few")
        continue
    period_ms = 1000.0 * (on[-1] - on[0]) / (len(on) - 1) / 2  # on every two sleeps
    expect(abs(period_ms / want_ms - 1) < 5e-4,
           f"robot {robot}: a Sys_Sleep(1000) lasts {period_ms:.2f} ms of world time ({want_ms:.2f} expected), "
           f"over {len(on)} blinks")
lines = open(log).read().splitlines()
expect(len(lines) == 1 and lines[0].startswith("fault t=0.000000 robot=1 kind=clock-drift ppm=+20000 "),
       f"the fault log has the drift: {lines}")
sys.exit(1 if failed else 0)
