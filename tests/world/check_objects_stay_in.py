#!/usr/bin/env python3
"""Objects pushed into walls and obstacles stay out of them (world.objects_stay_in).

check_objects_stay_in.py SIM FIRMWARE WORLD OUT: robots push objects into
the arena's walls and an obstacle (worlds/pushed_objects.json). Objects
passed through both, at any mass (issue 30: the friction joint that brakes
an object held on to the walls' own body, and Box2D does not collide the
bodies a joint connects). Checks, at every sample:
  each object's disc lies inside the arena (0.5 mm of overlap allowed:
  Box2D's contact slop is 0.05 mm);
  no object's disc reaches into the obstacle by more than that;
and that the test pushes: at the end each object touches a wall or the
obstacle (else the checks above prove nothing).
"""
import csv
import json
import subprocess
import sys

from behaviour import Checks

sim, firmware, world_file, out = sys.argv[1:5]
SLOP = 0.5
done = subprocess.run([sim, "--world", world_file, "--out", out, "-q", "--no-progress", firmware],
                      capture_output=True, text=True)
checks = Checks()
checks.expect(done.returncode == 0, f"the run ends with status 0 ({done.returncode}): {done.stderr.strip()}")
if done.returncode != 0:
    checks.finish()
world = json.load(open(world_file))
W, H = world["arena"]["width_mm"], world["arena"]["height_mm"]
rect = world["obstacles"][0]["rect"]
x0, y0, x1, y1 = rect["x_mm"], rect["y_mm"], rect["x_mm"] + rect["width_mm"], rect["y_mm"] + rect["height_mm"]
radius = [o["radius_mm"] for o in world["objects"]]


def distance_to_obstacle(x, y):
    """From a centre to the rectangle (0 inside it)."""
    dx, dy = max(x0 - x, 0, x - x1), max(y0 - y, 0, y - y1)
    return (dx * dx + dy * dy) ** 0.5


outside, inside, last = [], [], {}
for row in csv.DictReader(open(f"{out}/objects.csv")):
    k, t, x, y = int(row["object"]), float(row["time_s"]), float(row["x_mm"]), float(row["y_mm"])
    r = radius[k]
    last[k] = (x, y)
    if min(x - r, W - r - x, y - r, H - r - y) < -SLOP:
        outside.append(f"objects[{k}] at {t} s: ({x}, {y})")
    if distance_to_obstacle(x, y) < r - SLOP:
        inside.append(f"objects[{k}] at {t} s: ({x}, {y})")
checks.expect(not outside, "every object stays inside the arena: " + ("; ".join(outside[:3]) or "yes"))
checks.expect(not inside, "no object enters the obstacle: " + ("; ".join(inside[:3]) or "yes"))
for k, (x, y) in sorted(last.items()):
    r = radius[k]
    gap = min(x - r, W - r - x, y - r, H - r - y, distance_to_obstacle(x, y) - r)
    checks.expect(gap <= 1, f"objects[{k}] was pushed against a wall or the obstacle: ends {gap:.2f} mm from it")
checks.finish()
