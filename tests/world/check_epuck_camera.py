#!/usr/bin/env python3
"""The e-puck camera's rate and lag ("camera": {"frames_per_s", "lag_ms"}),
with the stand-in controller (epuck_double.py) logging every step's input:

  by default a frame comes every 250 ms, from the first step on;
  at 10 frames a second, every 100 ms;
  with a lag, frames come lag_ms later and show what the camera saw then:
  a robot spinning among objects sees the same sequence of centre pixels
  as without the lag, each arriving lag_ms later;
  twice the field of view, an object straight ahead half as many pixels
  wide; past the camera's range it shows as the wall behind;
  rates and lags off the 10 ms step are refused at their place;
  the camera's noise given as 0 changes nothing, byte for byte; pixel
  noise moves the pixels, the same way for the same seed; noise settings
  out of range are refused at their place, the field named.

check_epuck_camera.py SIM DOUBLE WORKDIR
"""
import json
import os
import shutil
import subprocess
import sys

SIM, DOUBLE, WORK = sys.argv[1:4]
failures = []
OBJECTS = [{"x_mm": 500 + dx, "y_mm": 400 + dy, "radius_mm": 30}
           for dx, dy in ((150, 0), (0, 150), (-150, 0))]


def run(name, camera, expect=0, objects=OBJECTS, wheels="150,-150", size=(1000, 800)):
    """A robot spinning on the spot among three objects, 3 s."""
    path = os.path.join(WORK, name + ".json")
    world = {"robot": "epuck", "arena": {"width_mm": size[0], "height_mm": size[1]}, "duration_s": 3,
             "noise": {"wheels": False}, "objects": objects,
             "robots": [{"poses": [{"x_mm": 500, "y_mm": 400, "heading_deg": 0}], "firmware": DOUBLE}]}
    if camera is not None:
        world["camera"] = camera
    with open(path, "w") as f:
        json.dump(world, f)
    log = os.path.join(WORK, name + "-")
    for old in (log + "0.log",):
        if os.path.exists(old):
            os.remove(old)
    out = os.path.join(WORK, name)
    shutil.rmtree(out, ignore_errors=True)
    done = subprocess.run([SIM, "-q", "--world", path, "--out", out],
                          env={**os.environ, "EPUCK_WHEELS": wheels, "EPUCK_LOG": log},
                          capture_output=True, text=True, timeout=300)
    if done.returncode != expect:
        failures.append(f"{name}: exit {done.returncode}, expected {expect}:\n{done.stderr}")
        return [], done.stderr
    if expect != 0:
        return [], done.stderr
    with open(log + "0.log") as f:
        rows = [line.split() for line in f]
    # (time the frame arrived in ms, the centre pixel it showed); the log's
    # time is the end of the step the input began.
    return [(int(r[0]) - 10, r[2], int(r[4])) for r in rows if r[3] == "1"], done.stderr


def check(name, ok, detail):
    if not ok:
        failures.append(f"{name}: {detail}")


os.makedirs(WORK, exist_ok=True)

plain, _ = run("default", None)
times = [t for t, *_ in plain]
check("default rate", times[:4] == [0, 250, 500, 750] and len(times) == 12,
      f"frames at {times[:6]}... ({len(times)} in 3 s), expected every 250 ms from 0 (12)")
colours = {c for _, c, _ in plain}
check("spinning robot", len(colours) >= 2, f"saw only {colours}: the test needs a changing view")

fast, _ = run("ten", {"frames_per_s": 10})
times = [t for t, *_ in fast]
check("10 frames a second", times[:4] == [0, 100, 200, 300] and len(times) == 30,
      f"frames at {times[:6]}... ({len(times)} in 3 s), expected every 100 ms (30)")

late, _ = run("lag", {"lag_ms": 120})
check("lag: arrival", [t for t, *_ in late][:3] == [120, 370, 620],
      f"frames at {[t for t, *_ in late][:4]}, expected 120, 370, 620 (taken at 0, 250, 500)")
check("lag: content", [c for _, c, _ in late] == [c for _, c, _ in plain][:len(late)] and len(late) == 12,
      f"centre pixels {[c for _, c, _ in late]} with the lag, {[c for _, c, _ in plain]} without: the same sequence expected")

longer, _ = run("long_lag", {"frames_per_s": 10, "lag_ms": 350})
check("lag over several frames", [t for t, *_ in longer][:3] == [350, 450, 550]
      and [c for _, c, _ in longer] == [c for _, c, _ in fast][:len(longer)],
      f"frames at {[t for t, *_ in longer][:4]}: expected the frames taken at 0, 100, ... arriving 350 ms later")

# An object straight ahead, 300 mm off (30 mm radius: 11.4 deg wide), the robot still.
AHEAD = [{"x_mm": 800, "y_mm": 400, "radius_mm": 30}]
seen = {}
for fov in (56, 112):
    frames, _ = run(f"fov{fov}", {"fov_deg": fov}, objects=AHEAD, wheels="0,0")
    seen[fov] = frames[0][2] if frames else 0
check("field of view", seen[56] >= 6 and abs(seen[56] / max(seen[112], 1) - 2) <= 0.5,
      f"the object {seen[56]} pixels wide at 56 deg, {seen[112]} at 112: expected about 8 and half as many")
FAR = [{"x_mm": 1500, "y_mm": 400, "radius_mm": 30}]  # 1000 mm ahead
for name, range_mm, red in (("in_range", 1200, True), ("out_of_range", 800, False)):
    frames, _ = run(name, {"range_mm": range_mm}, objects=FAR, wheels="0,0", size=(2000, 800))
    centre = frames[0][1] if frames else None
    check(name, centre == ("0xf800" if red else "0xffff"),
          f"an object 1000 mm ahead, range {range_mm} mm: centre {centre}, expected {'red' if red else 'the white wall'}")

def same_file(a, b, name):
    with open(os.path.join(WORK, a, name), "rb") as f, open(os.path.join(WORK, b, name), "rb") as g:
        return f.read() == g.read()


pure = {"0xf800", "0x07e0", "0xffff", "0x0000"}
off, _ = run("noise_off", {"pixel_noise": 0, "misread_pct_per_m": 0})
check("noise off", off == plain and same_file("default", "noise_off", "trajectories.csv")
      and {c for _, c, _ in plain} <= pure,
      "with \"pixel_noise\": 0 and \"misread_pct_per_m\": 0 the frames or the trajectories differ from a world "
      f"without them, or a world without them shows colours off the pure ones: {sorted({c for _, c, _ in plain})}")
noisy, _ = run("pixel_noise", {"pixel_noise": 3})
again, _ = run("pixel_noise_again", {"pixel_noise": 3})
check("pixel noise", len({c for _, c, _ in noisy} - pure) >= 6 and noisy == again,
      f"centre pixels {[c for _, c, _ in noisy]} with pixel noise 3: expected colours off the pure ones, the same in "
      f"a second run of the same seed ({[c for _, c, _ in again]})")

for name, camera, words in (("bad_rate", {"frames_per_s": 3}, "must divide 100"),
                            ("bad_lag", {"lag_ms": 125}, "multiple of 10 ms"),
                            ("bad_key", {"fps": 4}, "fps"),
                            ("bad_pixel_noise", {"pixel_noise": -1}, "\"pixel_noise\": 2"),
                            ("bad_misread", {"misread_pct_per_m": 150}, "\"misread_pct_per_m\": 20")):
    _, err = run(name, camera, expect=2)
    check(name, name + ".json:" in err and words in err, f"expected an error at its place saying {words!r}: {err}")

if failures:
    print("\n".join(failures))
    sys.exit(1)
print("camera: rate, lag and refusals as declared")
