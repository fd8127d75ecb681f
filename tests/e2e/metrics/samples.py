#!/usr/bin/env python3
# A metric script as docs/experiments.md describes them: given the run's
# folder, it prints how many samples trajectories.csv holds (a value at the
# run's end) and how many robots each sample holds (TIME_S,NAME,VALUE).
import csv
import sys

robots_at = {}
with open(sys.argv[1] + "/trajectories.csv") as f:
    for row in csv.DictReader(f):
        robots_at[row["time_s"]] = robots_at.get(row["time_s"], 0) + 1
print("samples", len(robots_at))
print("time_s,name,value")
for t, n in robots_at.items():
    print(f"{t},robots_sampled,{n}")
