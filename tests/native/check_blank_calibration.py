#!/usr/bin/env python3
"""--faults blank:ROBOT in both modes: the robot's distance tables read
0xFF, and its estimates are what the exact mode's robot makes of them.

    check_blank_calibration.py SIM EXACT.elf NATIVE.so WORLD OUT

runs tests/avr/world_distances.c (nine robots standing still on a 40 mm
grid, each printing every distance it estimates; WORLD is
tests/world/worlds/distances.json) for 3 s with --faults blank:4 (the
centre robot, 40 and 57 mm from its neighbours) in both modes, and once
natively without, and checks:
  both logs have robot 4's blank calibration at 0 s;
  without it, robot 4's estimates are within 10 mm of 40 or 57 mm;
  with it, robot 4 estimates none of them under 90 mm in either mode,
  and its most frequent estimate is the same in both (the same blank
  tables, the same arithmetic on them).
"""
import collections
import csv
import os
import re
import subprocess
import sys

ROBOT = 4
HEARD = re.compile(r"heard \d+ at (\d+) mm")


def estimates(sim, robot, world, out, name, faults):
    """Robot ROBOT's estimates, and the fault log's lines."""
    os.makedirs(out, exist_ok=True)
    console, log = os.path.join(out, name + ".csv"), os.path.join(out, name + ".log")
    done = subprocess.run([sim, "--world", world, "--out", os.path.join(out, name), "--time", "3", "-q",
                           "--threads", "1", "--console-csv", console, "--faults", faults, "--fault-log", log,
                           robot], capture_output=True, text=True, timeout=300)
    if done.returncode != 0:
        sys.exit(f"openswarm-sim failed ({done.returncode}) on {robot}:\n{done.stderr}")
    with open(console) as f:
        mm = [int(m.group(1)) for row in csv.DictReader(f) if int(row["robot"]) == ROBOT
              for m in [HEARD.match(row["line"])] if m]
    with open(log) as f:
        return mm, f.read().split("\n")


def main():
    sim, elf, so, world, out = sys.argv[1:6]
    passed = failed = 0

    def expect(ok, what):
        nonlocal passed, failed
        print(("ok   " if ok else "FAIL ") + what)
        passed, failed = passed + bool(ok), failed + (not ok)

    plain, _ = estimates(sim, so, world, out, "native-plain", "seed=1")
    expect(plain and all(min(abs(mm - 40), abs(mm - 57)) <= 10 for mm in plain),
           f"native, calibrated: robot {ROBOT}'s {len(plain)} estimates near 40 or 57 mm ({sorted(set(plain))})")
    modes = {}
    for mode, robot in (("exact", elf), ("native", so)):
        mm, log = estimates(sim, robot, world, out, mode + "-blank", f"blank:{ROBOT}")
        modes[mode] = collections.Counter(mm)
        expect(f"fault t=0.000000 robot={ROBOT} kind=blank-calibration" in log,
               f"{mode}: the log has robot {ROBOT}'s blank calibration")
        expect(mm and min(mm) >= 90, f"{mode}, blank: robot {ROBOT}'s {len(mm)} estimates all 90 mm or more "
               f"({sorted(set(mm))})")
    top = {mode: c.most_common(1)[0][0] if c else None for mode, c in modes.items()}
    expect(top["exact"] == top["native"], f"the most frequent blank estimate is the same in both modes: {top}")
    print(f"{passed} passed, {failed} failed")
    sys.exit(1 if failed else 0)


main()
