#!/usr/bin/env python3
"""Robots that walk up the light reach the lamp (world_phototaxis.elf).

check_phototaxis.py SIM ELF WORLD OUT: runs worlds/phototaxis.json, a lamp
and robots 400 mm from it facing away, and checks:
  every robot ends less than half as far from the lamp as it started;
  in the same world without the lamp (OUT/dark.json: same robots, same
  seed, ambient light only) the same firmware brings none of them as near:
  each ends more than half as far as it started from where the lamp was
  (the approach is the light's doing, not the walk's).
"""
import json
import math
import os
import sys

from behaviour import Checks, paths, run


def distances(robots, lamp):
    return {i: (math.dist(p[0][1:3], lamp), math.dist(p[-1][1:3], lamp)) for i, p in sorted(robots.items())}


def main():
    sim, elf, world, out = sys.argv[1:5]
    with open(world) as f:
        spec = json.load(f)
    source = spec["light"]["sources"][0]
    lamp = (source["x_mm"], source["y_mm"])
    checks = Checks()

    run(sim, elf, world, f"{out}/light")
    robots = paths(f"{out}/light")
    for i, (start, end) in distances(robots, lamp).items():
        checks.expect(end < 0.5 * start, f"with the lamp robot {i} ends nearer: {start:.0f} -> {end:.0f} mm")

    spec["description"] = "phototaxis.json without its lamp (written by check_phototaxis.py)"
    spec["light"]["sources"] = []
    os.makedirs(out, exist_ok=True)
    dark = f"{out}/dark.json"
    with open(dark, "w") as f:
        json.dump(spec, f, indent=1)
    run(sim, elf, dark, f"{out}/dark")
    robots = paths(f"{out}/dark")
    for i, (start, end) in distances(robots, lamp).items():
        checks.expect(end > 0.5 * start, f"without the lamp robot {i} does not close in on its place: "
                      f"{start:.0f} -> {end:.0f} mm")
    checks.finish()


main()
