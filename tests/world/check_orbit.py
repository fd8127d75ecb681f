#!/usr/bin/env python3
"""A planet orbits a star at the distance it measures (world_orbit.elf).

check_orbit.py SIM ELF WORLD OUT: runs worlds/orbit.json, a still star (robot
0, uid 1) sending messages and a planet (robot 1) keeping ORBIT_MM from it by
its IR distance estimates, which starts 80 mm away facing away from the star
(it is in the band within about 5 s), and checks:
  the star stays where it is;
  after SETTLE_S the planet's centre stays within ORBIT_MM +- BAND_MM of the
  star's, and on average within +- 10 mm: the firmware turns one way or
  the other at every message (one each 0.52 s) and walks straight only
  nearer than 40 mm, a turn on one motor also moves the centre (it pivots
  about a rear leg), and the estimate itself is off by a few mm, so +- 20
  mm (a third of the radius; the IR range is 100 mm) is what "keeps its
  distance" means;
  it goes round: its angle around the star sweeps one full turn or more
  clockwise after SETTLE_S (the classic planet keeps the star on its right).
"""
import math
import sys

from behaviour import Checks, paths, run

ORBIT_MM = 60.0
BAND_MM = 20.0
SETTLE_S = 20.0


def main():
    sim, elf, world, out = sys.argv[1:5]
    run(sim, elf, world, out)
    robots = paths(out)
    checks = Checks()
    star, planet = robots[0], robots[1]
    drift = math.dist(star[0][1:3], star[-1][1:3])
    checks.expect(drift < 2.0, f"the star stays still: it moved {drift:.2f} mm")
    sx, sy = star[-1][1:3]
    late = [(t, x - sx, y - sy) for t, x, y, _, _ in planet if t >= SETTLE_S]
    distances = [math.hypot(dx, dy) for _, dx, dy in late]
    low, high = min(distances), max(distances)
    checks.expect(ORBIT_MM - BAND_MM <= low and high <= ORBIT_MM + BAND_MM,
                  f"after {SETTLE_S:.0f} s the planet keeps {ORBIT_MM:.0f} +- {BAND_MM:.0f} mm from the star: "
                  f"{low:.1f} to {high:.1f} mm over {late[-1][0] - late[0][0]:.0f} s")
    mean = sum(distances) / len(distances)
    checks.expect(abs(mean - ORBIT_MM) <= 10.0, f"on average {mean:.1f} mm from the star")
    swept, last = 0.0, None
    for _, dx, dy in late:
        a = math.degrees(math.atan2(dy, dx))
        if last is not None:
            swept -= (a - last + 180.0) % 360.0 - 180.0
        last = a
    checks.expect(swept >= 360.0, f"it goes round the star clockwise: {swept:.0f} deg "
                  f"({swept / 360.0:.1f} turns) in {late[-1][0] - late[0][0]:.0f} s")
    checks.finish()


main()
