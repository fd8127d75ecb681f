#!/usr/bin/env python3
"""The gradient re-forms after faults (world_gradient.elf on worlds/gradient.json).

check_gradient_faults.py SIM ELF WORLD OUT: the seed robot (uid 1) loses its
power for 3 s at 6 s (--faults brownout:SEED@6,brownout-ms=3000), a robot
two hops away resets at 12 s and one at random has its calibration blank
(the template does not move, so it runs as the others); the faults are
logged to OUT/faults.log. Checks:
  the log names each fault, at its time and robot;
  the seed is dark while its power is off (at 6.5 and 8.5 s), and the reset
  robot right after its reset (at 12 s): a reset turns the LED off;
  at the end every robot shows the colour of its hop count again, as
  without faults (check_gradient.py).
"""
import json
import math
import os
import sys

from behaviour import Checks, paths, run
from check_gradient import COLOURS, SEED_UID, WHITE, hops_from, uids

DARK = (0, 0, 0)
OUTAGE_S, CHECK_DARK_S, RESET_S = 6.0, 8.5, 12.0


def led_at(samples, t):
    """The LED of the last sample at or before t."""
    return [s for s in samples if s[0] <= t + 1e-9][-1][4]


def main():
    sim, elf, world, out = sys.argv[1:5]
    with open(world) as f:
        spec = json.load(f)
    reach = spec.get("ir", {}).get("range_mm", 100)
    seed = uids(spec).index(SEED_UID)
    os.makedirs(out, exist_ok=True)
    log = os.path.join(out, "faults.log")
    # Where the robots stand comes from the world alone: a run without
    # faults would place them the same; the hop counts follow from it.
    run(sim, elf, world, out, ["--time", "0.01"])
    robots = paths(out)
    at = [robots[i][0][1:3] for i in range(len(robots))]
    hops = hops_from(seed, at, reach)
    two_hops = min(i for i in hops if hops[i] == 2)
    faults = f"brownout:{seed}@{OUTAGE_S},brownout-ms=3000,reset:{two_hops}@{RESET_S},blank=1,seed=4"
    run(sim, elf, world, out, ["--faults", faults, "--fault-log", log])
    robots = paths(out)
    checks = Checks()

    with open(log) as f:
        lines = [dict(kv.split("=", 1) for kv in line.split()[1:]) for line in f]
    kinds = [(line["kind"], int(line["robot"]), float(line["t"])) for line in lines]
    checks.expect(("brownout", seed, OUTAGE_S) in kinds, f"the log has robot {seed}'s brown-out at {OUTAGE_S} s")
    checks.expect(("reset", two_hops, RESET_S) in kinds, f"the log has robot {two_hops}'s reset at {RESET_S} s")
    checks.expect(sum(k == "blank-calibration" for k, _, _ in kinds) == 1, "the log has one blank calibration")

    for i, t in ((seed, OUTAGE_S + 0.5), (seed, CHECK_DARK_S), (two_hops, RESET_S)):
        got = led_at(robots[i], t)
        checks.expect(got == DARK, f"at {t} s robot {i} ({hops[i]} hops) is dark: {got}")
    for i in range(len(robots)):
        want = COLOURS.get(hops[i], WHITE)
        got = robots[i][-1][4]
        checks.expect(got == want, f"at the end robot {i} ({hops[i]} hops) shows {got} again, expected {want}")
    checks.finish()


main()
