#!/usr/bin/env python3
"""A classic kilolib program runs natively as on the robot
(programs/census.c): check_census.py SIM ROBOT.so runs four robots 50 mm
apart for 10 s and checks
  every robot reports once a kilo second (31 kilo ticks), ten times: its
  busy loop() lets time pass;
  each reports its own uid: the globals kilo_uid, heard, senders are each
  robot's own, not shared;
  each heard the three others, and about as many messages as they sent
  (a message every 0.52 s from each: 3 x 19 in 10 s, less what collided);
  loop() ran tens of thousands of times a second, as the robot's does
  (about 78 000 under simavr: within a factor 2, the native mode's
  charge per basic block being an average);
  the same run twice gives the same output, line for line.
"""
import re
import subprocess
import sys

sim, robot = sys.argv[1:3]
LINE = re.compile(r"\[robot (\d)\] uid (\d+) tick (\d+): (\d+) messages from (\d+) robots, (\d+) loops, sent (\d+)")


def run():
    done = subprocess.run([sim, "--robots", "4", "--distance", "50", "--time", "10", robot],
                          capture_output=True, text=True, timeout=120)
    if done.returncode != 0:
        sys.exit(f"openswarm-sim failed ({done.returncode}):\n{done.stderr}")
    return done.stdout


out = run()
reports = {}
for m in LINE.finditer(out):
    index, uid, tick, heard, senders, loops, sent = map(int, m.groups())
    reports.setdefault(index, []).append((uid, tick, heard, senders, loops, sent))
checks = {}
checks["four robots report"] = sorted(reports) == [0, 1, 2, 3]
for index, rows in sorted(reports.items()):
    uid, tick, heard, senders, loops, sent = rows[-1]
    checks[f"robot {index} reports 9 or 10 times, once every 31 ticks ({[r[1] for r in rows]})"] = (
        len(rows) in (9, 10) and all(b[1] - a[1] == 31 for a, b in zip(rows, rows[1:])))
    checks[f"robot {index} has its own uid ({uid})"] = uid == index + 1
    checks[f"robot {index} heard the 3 others ({senders})"] = senders == 3
    checks[f"robot {index} heard 30 to 60 messages ({heard} by tick {tick})"] = 30 <= heard <= 60
    per_second = loops / (tick / 30.52)
    checks[f"robot {index}: loop() {per_second:.0f} times a second, 39 000 to 156 000"] = (
        39000 <= per_second <= 156000)
checks["a second run prints the same"] = run() == out
for what, ok in checks.items():
    print(("ok   " if ok else "FAIL ") + what)
failed = sum(not ok for ok in checks.values())
print(f"{len(checks) - failed} passed, {failed} failed")
sys.exit(1 if failed else 0)
