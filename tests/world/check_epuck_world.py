#!/usr/bin/env python3
"""The e-puck in the world (world.json "robot": "epuck"), with a stand-in
controller (epuck_double.py) in place of a real one:

  wheels at 500 steps/s each: straight at 500 x pi x 41 / 1000 = 64.4 mm/s;
  wheels at +-300: a spin at (v_r - v_l) / 53 mm rad/s on the spot;
  into a wall: it stops at the wall;
  the camera shows an object red, a robot green, a wall white (the stand-in
  lights its LED with what the frame's centre shows);
  the proximity sensors see a wall closer as more reflected light;
  a controller that dies, or answers nonsense, fails the run saying so;
  the same world twice: the same trajectories, byte for byte.

check_epuck_world.py SIM DOUBLE WORKDIR
"""
import csv
import json
import math
import os
import shutil
import subprocess
import sys

SIM, DOUBLE, WORK = sys.argv[1:4]
MM_PER_STEP = math.pi * 41 / 1000
failures = []


def world(name, robots, objects=(), duration=2.0, size=(1000, 800)):
    """The wheels without their noise: these checks are of the drive's
    geometry, to the millimetre (world.EpuckWheelNoise checks the noise)."""
    path = os.path.join(WORK, name + ".json")
    with open(path, "w") as f:
        json.dump({"robot": "epuck", "arena": {"width_mm": size[0], "height_mm": size[1]},
                   "noise": {"wheels": False},
                   "duration_s": duration, "sample_period_s": 0.1, "objects": list(objects),
                   "robots": [{"poses": robots, "firmware": DOUBLE}]}, f)
    return path


def run(name, env, expect=0, **kw):
    out = os.path.join(WORK, name)
    shutil.rmtree(out, ignore_errors=True)
    done = subprocess.run([SIM, "-q", "--world", world(name, **kw), "--out", out],
                          env={**os.environ, **env}, capture_output=True, text=True, timeout=120)
    if done.returncode != expect:
        failures.append(f"{name}: exit {done.returncode}, expected {expect}:\n{done.stderr}")
    return out, done.stderr


def track(out, robot=0):
    with open(os.path.join(out, "trajectories.csv")) as f:
        return [r for r in csv.DictReader(f) if int(r["robot"]) == robot]


def check(name, ok, detail):
    if not ok:
        failures.append(f"{name}: {detail}")


os.makedirs(WORK, exist_ok=True)

out, _ = run("straight", {"EPUCK_WHEELS": "500,500"}, robots=[{"x_mm": 200, "y_mm": 400, "heading_deg": 0}])
p = track(out)
moved = float(p[-1]["x_mm"]) - 200
check("straight", abs(moved - 2 * 500 * MM_PER_STEP) < 2.0 and abs(float(p[-1]["y_mm"]) - 400) < 0.5,
      f"moved {moved:.1f} mm in 2 s, expected {2 * 500 * MM_PER_STEP:.1f}")

out, _ = run("spin", {"EPUCK_WHEELS": "300,-300"}, duration=1.0,
             robots=[{"x_mm": 500, "y_mm": 400, "heading_deg": 90}])
p = track(out)
turned = (float(p[-1]["heading_deg"]) - 90 + 540) % 360 - 180
expected = math.degrees(-2 * 300 * MM_PER_STEP / 53)
check("spin", abs(turned - expected) < 2.0 and math.dist((500, 400), (float(p[-1]["x_mm"]), float(p[-1]["y_mm"]))) < 1,
      f"turned {turned:.1f} deg in 1 s, expected {expected:.1f}, on the spot")

out, _ = run("wall", {"EPUCK_WHEELS": "800,800"}, duration=5.0, size=(400, 400),
             robots=[{"x_mm": 100, "y_mm": 200, "heading_deg": 0}])
x = float(track(out)[-1]["x_mm"])
check("wall", 400 - 37 - 1.5 <= x <= 400 - 37 + 0.5, f"stopped at x {x:.1f}, the wall is at 400 - 37")

log = os.path.join(WORK, "seen")
for f in os.listdir(WORK):
    if f.startswith("seen"):
        os.remove(os.path.join(WORK, f))
out, _ = run("camera", {"EPUCK_LOG": log}, duration=0.5,
             objects=[{"x_mm": 600, "y_mm": 600, "radius_mm": 40}],
             robots=[{"x_mm": 300, "y_mm": 600, "heading_deg": 0},      # faces the object
                     {"x_mm": 300, "y_mm": 200, "heading_deg": 0},      # faces robot 2
                     {"x_mm": 600, "y_mm": 200, "heading_deg": -90}])   # faces the wall below
leds = [(int(r["led_r"]), int(r["led_g"]), int(r["led_b"])) for r in (track(out, k)[-1] for k in range(3))]
check("camera", leds == [(3, 0, 0), (0, 3, 0), (3, 3, 3)], f"LEDs {leds}: expected red, green, white")

out, _ = run("proximity", {"EPUCK_LOG": log + "p", "EPUCK_WHEELS": "200,200"}, duration=7.0, size=(400, 400),
             robots=[{"x_mm": 200, "y_mm": 200, "heading_deg": 0}])
with open(log + "p0.log") as f:
    front = [int(line.split()[1]) for line in f]
check("proximity", front[0] < 40 and front[-1] > 2500 and max(front[:50]) < min(front[-20:]),
      f"front reflected from {front[0]} to {front[-1]}: expected near 0 far off, above 2500 at the wall")

_, err = run("dies", {"EPUCK_DIE_AT": "500"}, expect=3, robots=[{"x_mm": 200, "y_mm": 200}])
check("dies", "robot 0's controller" in err and "exited with status 5 while" in err, err)
_, err = run("garbage", {"EPUCK_GARBAGE": "1"}, expect=3, robots=[{"x_mm": 200, "y_mm": 200}])
check("garbage", "answered 0x12345678, not an e-puck link record" in err, err)

a, _ = run("same_a", {"EPUCK_WHEELS": "700,400"}, duration=3.0, robots=[{"x_mm": 300, "y_mm": 300}, {"x_mm": 500, "y_mm": 300}])
b, _ = run("same_b", {"EPUCK_WHEELS": "700,400"}, duration=3.0, robots=[{"x_mm": 300, "y_mm": 300}, {"x_mm": 500, "y_mm": 300}])
with open(os.path.join(a, "trajectories.csv"), "rb") as fa, open(os.path.join(b, "trajectories.csv"), "rb") as fb:
    check("same run", fa.read() == fb.read(), "two runs of one world differ")

for f in failures:
    print("FAILED:", f)
print(f"{9 - len(failures)} passed, {len(failures)} failed")
sys.exit(1 if failures else 0)
