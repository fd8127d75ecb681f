#!/usr/bin/env python3
"""The gradient template's program on a random cluster (world_gradient.elf,
templates/gradient/main.c).

check_gradient.py SIM ELF WORLD OUT: runs worlds/gradient.json, robots placed
at random in a region, and checks:
  the robots stay where they were placed (the template does not move them);
  the cluster is connected over the IR range (ir.range_mm, 100 mm by
  default) and no two robots are within 0.5 mm of that range (the channel
  compares exact centre distances with it; trajectories.csv rounds to 0.01
  mm, and a pair that close would make rounding decide the answer: pick
  another seed);
  the hop counts from the seed (uid 1), by breadth-first search over the
  robots that are in range of each other, reach 3 or more, so every colour
  is used;
  each robot's LED at the end is the colour the template gives its hop
  count: red 0, green 1, blue 2, white 3 or more.
"""
import json
import math
import sys
from collections import deque

from behaviour import Checks, paths, run

SEED_UID = 1
COLOURS = {0: (3, 0, 0), 1: (0, 3, 0), 2: (0, 0, 3)}
WHITE = (3, 3, 3)
MARGIN_MM = 0.5


def uids(spec):
    """Each robot's uid, in order (docs/world.md, "robots")."""
    result, next_uid = [], 1
    for group in spec.get("robots", []):
        if "poses" in group:
            n = len(group["poses"])
        elif "grid" in group:
            n = group["grid"]["columns"] * group["grid"]["rows"]
        else:
            n = group["count"]
        next_uid = group.get("uid", next_uid)
        result += range(next_uid, next_uid + n)
        next_uid += n
    return result


def hops_from(seed, at, reach):
    hops = {seed: 0}
    queue = deque([seed])
    while queue:
        i = queue.popleft()
        for j in range(len(at)):
            if j not in hops and math.dist(at[i], at[j]) <= reach:
                hops[j] = hops[i] + 1
                queue.append(j)
    return hops


def main():
    sim, elf, world, out = sys.argv[1:5]
    with open(world) as f:
        spec = json.load(f)
    reach = spec.get("ir", {}).get("range_mm", 100)
    run(sim, elf, world, out)
    robots = paths(out)
    checks = Checks()
    n = len(robots)
    at = [robots[i][0][1:3] for i in range(n)]
    moved = max(math.dist(robots[i][0][1:3], robots[i][-1][1:3]) for i in range(n))
    checks.expect(moved < 1.0, f"the {n} robots stay where they are: the most any moved is {moved:.2f} mm")

    close = [(i, j, math.dist(at[i], at[j])) for i in range(n) for j in range(i + 1, n)
             if abs(math.dist(at[i], at[j]) - reach) < MARGIN_MM]
    if close:
        sys.exit(f"{world}: robots {close[0][0]} and {close[0][1]} are {close[0][2]:.2f} mm apart, within {MARGIN_MM} mm "
                 f"of the IR range ({reach} mm): rounding decides whether they hear each other; choose another seed")
    seed = uids(spec).index(SEED_UID)
    hops = hops_from(seed, at, reach)
    if len(hops) < n:
        alone = sorted(set(range(n)) - set(hops))
        sys.exit(f"{world}: the cluster is not connected over the IR range ({reach} mm): robots {alone} cannot "
                 f"be reached from the seed (robot {seed}); choose another seed or a smaller region")
    deepest = max(hops.values())
    checks.expect(deepest >= 3, f"the cluster is {deepest} hops deep from the seed, so every colour is used")

    for i in range(n):
        want = COLOURS.get(hops[i], WHITE)
        got = robots[i][-1][4]
        checks.expect(got == want, f"robot {i} ({hops[i]} hops) shows {got}, expected {want}")
    checks.finish()


if __name__ == "__main__":
    main()
