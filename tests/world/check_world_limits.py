#!/usr/bin/env python3
"""A world at the limits loads and runs (world.at_the_limits).

check_world_limits.py SIM FIRMWARE OUT: writes OUT/limits.json, a world at
docs/world.md's limits - 1000 obstacles of 4000 vertices in all, every one
overlapping every other (the worst case for Box2D's broad phase, which
pairs them when the world starts), and 10000 objects - with three robots,
and runs it for a few physics steps. 10000 identical obstacles took 2.7 GB
and crashed in Box2D's broad phase (issue 30); at the limit the run takes
about 60 MB more than an empty world. Checks: the run ends with status 0.
"""
import json
import os
import subprocess
import sys

from behaviour import Checks

sim, firmware, out = sys.argv[1:4]
os.makedirs(out, exist_ok=True)
obstacles = [{"rect": {"x_mm": 100 + k * 0.01, "y_mm": 100, "width_mm": 50, "height_mm": 20}} for k in range(1000)]
objects = [{"x_mm": 1000 + (k % 100) * 20, "y_mm": 1000 + (k // 100) * 20, "radius_mm": 5} for k in range(10000)]
world = {"arena": {"width_mm": 4000, "height_mm": 4000}, "duration_s": 0.05, "obstacles": obstacles,
         "objects": objects, "robots": [{"poses": [{"x_mm": 3500, "y_mm": 3500 - 50 * k} for k in range(3)]}]}
path = os.path.join(out, "limits.json")
with open(path, "w") as f:
    json.dump(world, f)
done = subprocess.run([sim, "--world", path, "-q", "--no-progress", firmware], capture_output=True, text=True)
checks = Checks()
checks.expect(done.returncode == 0, f"the world at the limits runs, status 0 ({done.returncode}): {done.stderr.strip()}")
checks.finish()
