#!/usr/bin/env python3
"""Two apps in one world, natively (native.two_apps): each robot runs its
own group's app, and the files are the same on one thread and on two.
check_two_apps.py SIM WORLD OUT, WORLD's robots 0-5 running disperse (LED
red or green, never blue), 6-7 the blinker (LED blue or off, both seen,
never red or green)."""
import csv
import filecmp
import subprocess
import sys

sim, world, out = sys.argv[1:4]
for run, threads in (("first", "1"), ("second", "2")):
    done = subprocess.run([sim, "--world", world, "--out", f"{out}/{run}", "--threads", threads, "-q"],
                          capture_output=True, text=True, timeout=240)
    if done.returncode != 0:
        sys.exit(f"openswarm-sim --threads {threads} failed ({done.returncode}):\n{done.stderr}")

failed = 0
for name in ("trajectories.csv", "objects.csv"):
    if not filecmp.cmp(f"{out}/first/{name}", f"{out}/second/{name}", shallow=False):
        print(f"FAIL {name} differs between the runs on one thread and on two")
        failed += 1

colours = {}  # robot -> the LED colours sampled (r, g, b)
with open(f"{out}/first/trajectories.csv") as f:
    for row in csv.DictReader(f):
        colours.setdefault(int(row["robot"]), set()).add((int(row["led_r"]), int(row["led_g"]), int(row["led_b"])))

DISPERSE = {(3, 0, 0), (0, 3, 0), (0, 0, 0)}
BLINK = {(0, 0, 3), (0, 0, 0)}
for robot, seen in sorted(colours.items()):
    app, allowed = ("disperse", DISPERSE) if robot < 6 else ("blink", BLINK)
    if not seen <= allowed:
        print(f"FAIL robot {robot} ({app}) showed {sorted(seen - allowed)}: another app's colours")
        failed += 1
    elif app == "blink" and seen != BLINK:
        print(f"FAIL robot {robot} (blink) showed only {sorted(seen)}: it does not blink")
        failed += 1
    elif app == "disperse" and (3, 0, 0) not in seen:
        print(f"FAIL robot {robot} (disperse, 40 mm from its neighbours) never walked away (red)")
        failed += 1
if sorted(colours) != list(range(8)):
    print(f"FAIL robots {sorted(colours)} in trajectories.csv, expected 0-7")
    failed += 1
print("PASS" if failed == 0 else f"{failed} failed")
sys.exit(1 if failed else 0)
