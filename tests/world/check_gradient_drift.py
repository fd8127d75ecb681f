#!/usr/bin/env python3
"""The gradient forms with every robot's clock off by up to a few percent
(world_gradient.elf on worlds/gradient.json).

check_gradient_drift.py SIM ELF WORLD OUT PCT: --faults drift=PCT gives each
robot a clock between PCT% slow and PCT% fast (drawn from the seed), logged
to OUT/faults.log. Checks:
  the log has one drift for every robot, each within PCT%, and they spread
  over at least PCT% in all (robots fast and slow, not all alike);
  at the end every robot shows the colour of its hop count, as with exact
  clocks (check_gradient.py): their messages still reach each other.
"""
import json
import os
import sys

from behaviour import Checks, paths, run
from check_gradient import COLOURS, SEED_UID, WHITE, hops_from, uids


def main():
    sim, elf, world, out, pct = sys.argv[1:6]
    pct = float(pct)
    with open(world) as f:
        spec = json.load(f)
    reach = spec.get("ir", {}).get("range_mm", 100)
    seed = uids(spec).index(SEED_UID)
    os.makedirs(out, exist_ok=True)
    log = os.path.join(out, "faults.log")
    run(sim, elf, world, out, ["--faults", f"drift={pct},seed=3", "--fault-log", log])
    robots = paths(out)
    checks = Checks()

    with open(log) as f:
        lines = [dict(kv.split("=", 1) for kv in line.split()[1:]) for line in f]
    drift = {int(line["robot"]): int(line["ppm"]) / 1e4 for line in lines if line["kind"] == "clock-drift"}
    checks.expect(sorted(drift) == list(range(len(robots))), f"the log has a drift for each of the {len(robots)} robots")
    checks.expect(all(abs(d) <= pct for d in drift.values()), f"every drift within {pct}%")
    spread = max(drift.values(), default=0) - min(drift.values(), default=0)
    checks.expect(spread >= pct, f"the drifts spread over {spread:.2f}% (from {min(drift.values(), default=0):+.2f}% "
                  f"to {max(drift.values(), default=0):+.2f}%)")

    at = [robots[i][0][1:3] for i in range(len(robots))]
    hops = hops_from(seed, at, reach)
    for i in range(len(robots)):
        want = COLOURS.get(hops[i], WHITE)
        got = robots[i][-1][4]
        checks.expect(got == want, f"at the end robot {i} ({hops[i]} hops, clock {drift.get(i, 0):+.2f}%) shows "
                      f"{got}, expected {want}")
    checks.finish()


main()
