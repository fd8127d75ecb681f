#!/usr/bin/env python3
"""The disperse template's robots spread out: spread.py TRAJECTORIES.csv
ROBOTS SECONDS checks every sample has ROBOTS robots, the last is at
SECONDS (within 1 s), and the mean nearest-neighbour distance has grown
by half or more from the first sample to the last."""
import csv
import math
import sys

path, robots, seconds = sys.argv[1], int(sys.argv[2]), float(sys.argv[3])
samples = {}
for row in csv.DictReader(open(path)):
    samples.setdefault(float(row["time_s"]), []).append((float(row["x_mm"]), float(row["y_mm"])))


def mean_nearest(points):
    return sum(min(math.dist(p, q) for q in points if q is not p) for p in points) / len(points)


first, last = min(samples), max(samples)
assert len(samples[first]) == robots and len(samples[last]) == robots, f"expected {robots} robots in every sample"
assert last >= seconds - 1, f"the trajectories end at {last} s, not at the world's {seconds:g} s"
start, end = mean_nearest(samples[first]), mean_nearest(samples[last])
print(f"mean nearest-neighbour distance: {start:.1f} mm at {first} s, {end:.1f} mm at {last} s")
assert end >= 1.5 * start, f"the robots did not spread: {start:.1f} -> {end:.1f} mm (want x1.5)"
