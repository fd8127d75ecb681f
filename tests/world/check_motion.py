#!/usr/bin/env python3
"""Kilobots move as the model says (docs/world.md, "Kilobot motion").

check_motion.py SIM ELF WORLD OUT: runs world_walk.elf in worlds/motion.json
and checks each robot's path in trajectories.csv:
  robot 0 walks straight with its calibration: about 10 cm in 10 s;
  robot 1 turns left at its turn duty: about 45 deg/s;
  robot 2 (below the stall duty), robot 3 (no spin-up) and robot 4 (an erased
  EEPROM's 255: the legs slip) stay where they are;
  robot 5 walks into a wall and stops at it;
  robot 6 walks into an object and pushes it.
"""
import csv
import math
import subprocess
import sys


def run(sim, elf, world, out):
    done = subprocess.run([sim, "--world", world, "--out", out, "-q", elf],
                          capture_output=True, text=True, timeout=240)
    if done.returncode != 0:
        sys.exit(f"openswarm-sim failed ({done.returncode}):\n{done.stderr}")


def paths(out):
    robots, objects = {}, {}
    with open(f"{out}/trajectories.csv") as f:
        for row in csv.DictReader(f):
            robots.setdefault(int(row["robot"]), []).append(
                (float(row["time_s"]), float(row["x_mm"]), float(row["y_mm"]), float(row["heading_deg"])))
    with open(f"{out}/objects.csv") as f:
        for row in csv.DictReader(f):
            objects.setdefault(int(row["object"]), []).append(
                (float(row["time_s"]), float(row["x_mm"]), float(row["y_mm"])))
    return robots, objects


def moved(path):
    return math.dist(path[0][1:3], path[-1][1:3])


def turned_deg(path, t0, t1):
    """Counter-clockwise turn between two times, unwrapped."""
    total, last = 0.0, None
    for t, _, _, h in path:
        if t < t0 or t > t1:
            continue
        if last is not None:
            total += (h - last + 180.0) % 360.0 - 180.0
        last = h
    return total


failures = []


def expect(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


def main():
    sim, elf, world, out = sys.argv[1:5]
    run(sim, elf, world, out)
    robots, objects = paths(out)
    walked = moved(robots[0])
    expect(70 <= walked <= 130, f"straight duties walk about 100 mm in 10 s: {walked:.1f} mm")
    rate = turned_deg(robots[1], 1.0, 9.0) / 8.0
    expect(35 <= rate <= 55, f"the turn duty turns about 45 deg/s: {rate:.1f} deg/s")
    for i, why in ((2, "below the stall duty"), (3, "without a spin-up"), (4, "at an erased EEPROM's 255")):
        expect(moved(robots[i]) < 2.0, f"{why} it stays: moved {moved(robots[i]):.2f} mm")
    wall_x = 1250 - 16.5
    furthest = max(x for _, x, _, _ in robots[5])
    expect(furthest <= wall_x + 1.0 and robots[5][-1][1] >= wall_x - 3.0,
           f"a wall stops it: furthest x {furthest:.1f}, ends at {robots[5][-1][1]:.1f} (wall at {wall_x})")
    pushed = moved(objects[0])
    expect(pushed >= 20.0, f"it pushes an object: the object moved {pushed:.1f} mm")
    if failures:
        sys.exit(f"{len(failures)} of the motion checks failed")
    print("7 passed, 0 failed")


main()
