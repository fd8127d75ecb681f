#!/usr/bin/env python3
"""Every robot's motion noise is its own (docs/world.md, "Kilobot motion").

check_streams.py SIM ELF WORLD OUT: twelve robots walk straight for 20 s
(worlds/streams.json). Between two samples each robot moves a distance and
turns an angle that the motion noise varies; for every pair of robots the
correlation of those series is measured. Independent noise keeps it near
zero (about +-0.07 over 200 samples); a robot whose random stream is
another's shifted by a few draws repeats that robot's steps a moment
later, and the pair correlates near 1.
"""
import math
import os
import statistics
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from behaviour import paths, run  # noqa: E402

TWINS = 0.5  # far above chance (7 standard deviations), far below a shared stream


def steps(out):
    """Each robot's (distance moved, angle turned) between samples."""
    return {r: ([math.dist(a[1:3], b[1:3]) for a, b in zip(p, p[1:])],
                [(b[3] - a[3] + 180.0) % 360.0 - 180.0 for a, b in zip(p, p[1:])])
            for r, p in paths(out).items()}


def correlation(a, b):
    return statistics.correlation(a[:len(b)], b[:len(a)])


def main():
    sim, elf, world, out = sys.argv[1:5]
    run(sim, elf, world, out)
    moves = steps(out)
    robots = sorted(moves)
    if len(robots) != 12 or min(len(m[0]) for m in moves.values()) < 100:
        sys.exit(f"FAIL expected 12 robots sampled for 20 s, got {len(robots)}")
    alike = {(i, j): max(correlation(moves[i][0], moves[j][0]), correlation(moves[i][1], moves[j][1]))
             for i in robots for j in robots if i < j}
    closest = max(alike, key=alike.get)
    print(f"{len(alike)} pairs: the most alike {closest}, correlation {alike[closest]:.2f}")
    twins = sorted(p for p, c in alike.items() if c > TWINS)
    if twins:
        sys.exit("FAIL robots repeat each other's steps (their noise streams overlap): " +
                 ", ".join(f"{i} and {j} ({alike[i, j]:.2f})" for i, j in twins))
    print("ok   no two robots share their motion noise")


main()
