# Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later (see sim/COPYING).
"""world.output_trajectories: trajectories.csv and objects.csv of
output_driver's run (paths in output_driver.c): headers, one row per robot
(object) per sample, exact values, and the same bytes on a second run.
usage: check_trajectories.py DRIVER OUT_DIR"""
import os
import shutil
import subprocess
import sys

driver, out = sys.argv[1], sys.argv[2]
shutil.rmtree(out, ignore_errors=True)
failures = []


def check(ok, what):
    if not ok:
        failures.append(what)


def run(folder):
    p = subprocess.run([driver, folder], capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit(f"output_driver {folder} failed ({p.returncode}):\n{p.stderr}")
    return p.stderr


stderr = run(os.path.join(out, "a"))
check("wrote " in stderr and "trajectories.csv" in stderr and "viewer.html" in stderr,
      f"the list of files written: {stderr!r}")
robots = open(os.path.join(out, "a", "trajectories.csv")).read().splitlines()
objects = open(os.path.join(out, "a", "objects.csv")).read().splitlines()

check(robots[0] == "time_s,robot,x_mm,y_mm,heading_deg,led_r,led_g,led_b", f"header {robots[0]!r}")
check(len(robots) == 1 + 50 * 3, f"{len(robots) - 1} robot rows, expected 150")
check(objects[0] == "time_s,object,x_mm,y_mm", f"objects header {objects[0]!r}")
check(len(objects) == 1 + 50, f"{len(objects) - 1} object rows, expected 50")

expected_rows = [
    "0.000,0,50.00,50.00,0.0,3,0,0",
    "0.000,2,320.00,120.00,270.0,0,0,0",    # heading -90 printed in [0, 360)
    "1.900,2,320.00,120.00,270.0,0,0,0",    # LED off before 2.0 s
    "2.000,2,320.00,120.00,270.0,1,2,3",
    "2.400,0,98.00,50.00,0.0,3,0,0",
    "2.500,0,100.00,50.00,0.0,3,0,0",
    "2.500,1,200.00,210.00,180.0,0,3,0",    # a quarter turn: top of the circle
    "4.900,1,140.12,153.77,266.4,0,3,0",
]
for row in expected_rows:
    check(row in robots, f"trajectories.csv has no row {row!r}")
check(robots[1 + 3 * 25 + 1] == "2.500,1,200.00,210.00,180.0,0,3,0",
      f"rows out of order: row {1 + 3 * 25 + 1} is {robots[1 + 3 * 25 + 1]!r}")
check("0.000,0,100.00,220.00" in objects and "4.900,0,109.80,220.00" in objects,
      "objects.csv: object 0 from (100, 220) to (109.8, 220)")

run(os.path.join(out, "b"))
for name in ("trajectories.csv", "objects.csv", "viewer.html"):
    same = open(os.path.join(out, "a", name), "rb").read() == open(os.path.join(out, "b", name), "rb").read()
    check(same, f"{name} differs between two identical runs")

if failures:
    sys.exit("FAILED:\n  " + "\n  ".join(failures))
print("trajectories.csv and objects.csv: headers, 150 + 50 rows, values and bytes as expected")
