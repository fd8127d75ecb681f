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
import csv
import math
import statistics
import subprocess
import sys

TWINS = 0.5  # far above chance (7 standard deviations), far below a shared stream


def run(sim, elf, world, out):
    done = subprocess.run([sim, "--world", world, "--out", out, "-q", elf],
                          capture_output=True, text=True, timeout=240)
    if done.returncode != 0:
        sys.exit(f"openswarm-sim failed ({done.returncode}):\n{done.stderr}")


def steps(out):
    """Each robot's (distance moved, angle turned) between samples."""
    paths = {}
    with open(f"{out}/trajectories.csv") as f:
        for row in csv.DictReader(f):
            paths.setdefault(int(row["robot"]), []).append(
                (float(row["x_mm"]), float(row["y_mm"]), float(row["heading_deg"])))
    return {r: ([math.dist(a[:2], b[:2]) for a, b in zip(p, p[1:])],
                [(b[2] - a[2] + 180.0) % 360.0 - 180.0 for a, b in zip(p, p[1:])])
            for r, p in paths.items()}


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
