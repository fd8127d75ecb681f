# Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later (see sim/COPYING).
"""world.output_viewer_thinned: the run kept for viewer.html and final.png
is bounded. output_driver's 50 samples (t = 0.0 .. 4.9 s) with a budget of
a few kilobytes: the viewer holds every 2^k-th sample, from the first, and
always the last; each kept sample carries its own positions and IR links
(robot 0 at x = 50 + 20 t; links between robots within 100 mm), so the
thinning moved every part of a sample together.
usage: check_viewer_thinned.py DRIVER OUT_DIR"""
import json
import math
import os
import shutil
import subprocess
import sys

driver, out = sys.argv[1], sys.argv[2]
BUDGET = 3000
shutil.rmtree(out, ignore_errors=True)
p = subprocess.run([driver, out, "--quiet", "--history-bytes", str(BUDGET)], capture_output=True, text=True)
if p.returncode != 0:
    sys.exit(f"output_driver failed ({p.returncode}):\n{p.stderr}")
page = open(os.path.join(out, "viewer.html")).read()
run, _ = json.JSONDecoder().raw_decode(page[page.index('{"arena":'):])
samples = run["samples"]
times = [round(s[0] * 10) for s in samples]  # sample numbers, 0..49
failures = []
if len(samples) >= 50:
    failures.append(f"all {len(samples)} samples kept: a budget of {BUDGET} bytes thinned nothing")
if times[0] != 0 or times[-1] != 49:
    failures.append(f"the first and last samples must be kept: {times[0]} .. {times[-1]}")
stride = times[1] - times[0] if len(times) > 1 else 0
if stride < 2 or stride & (stride - 1):
    failures.append(f"the stride is {stride} samples, not a power of two above 1")
if times[:-1] != list(range(0, 50, stride))[:len(times) - 1]:
    failures.append(f"kept samples {times} are not every {stride}th from 0, then the last")
for s, k in zip(samples, times):
    t = k / 10
    robots = s[1]
    x0 = robots[0]
    if abs(x0 - (50 + 20 * t)) > 0.051:
        failures.append(f"sample {k}: robot 0 at x {x0}, not {50 + 20 * t:.1f}: positions moved apart from their time")
    pos = [(robots[4 * i], robots[4 * i + 1]) for i in range(3)]
    want = sorted((i, j) for i in range(3) for j in range(i + 1, 3)
                  if math.dist(pos[i], pos[j]) <= 100.05)
    got = sorted(zip(s[3][0::2], s[3][1::2]))
    if got != want:
        failures.append(f"sample {k}: links {got}, want {want}: links moved apart from their sample")
if failures:
    sys.exit("\n".join(failures))
print(f"viewer.html kept {len(samples)} of 50 samples, every {stride}th and the last, each whole")
