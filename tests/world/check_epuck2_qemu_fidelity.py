#!/usr/bin/env python3
"""The fidelity check of the e-puck in the world: the same controller
(tests/world/epuck_link_app.c: the clustering controller's camera-to-wheels
handler and a thread blinking the LEDs) drives two e-pucks among three
objects for 10 s, once built for the host (PORT epuck_world, the way the
case study runs) and once as the e-puck2 image under QEMU (board world,
ports/epuck/epuck2/qemu_world). The world's record of both runs - every
robot's pose and LEDs every 0.1 s, every object's position - must be the
same, byte for byte, and show the robots turning, pushing and blinking.

check_epuck2_qemu_fidelity.py SIM HOST_APP QEMU_ELF QEMU_SYSTEM_ARM WORKDIR
"""
import csv
import json
import math
import os
import shutil
import stat
import subprocess
import sys

SIM, HOST_APP, QEMU_ELF, QEMU, WORK = sys.argv[1:6]
failures = []


def qemu_controller():
    """The world starts a controller as a program without arguments: a
    script that runs the image in QEMU, the link on the second serial
    port (USART2) as its standard input and output, the robot's index in
    the world (OPENSWARM_ROBOT_ID) as its id."""
    path = os.path.join(WORK, "epuck2_in_qemu.sh")
    with open(path, "w") as f:
        f.write("#!/bin/sh\nexec %s -M netduinoplus2 -display none -monitor none "
                "-serial file:/dev/stderr -serial stdio "
                "-semihosting-config enable=on,target=native,arg=app,arg=--id=$OPENSWARM_ROBOT_ID "
                "-icount shift=3,align=off,sleep=off -kernel %s\n" % (QEMU, QEMU_ELF))
    os.chmod(path, os.stat(path).st_mode | stat.S_IXUSR)
    return path


def run(name, controller):
    world = os.path.join(WORK, name + ".json")
    objects = [{"x_mm": x, "y_mm": y, "radius_mm": 50, "mass_g": 50, "friction": 0.5}
               for x, y in ((600, 400), (300, 600), (700, 200))]
    with open(world, "w") as f:
        json.dump({"robot": "epuck", "arena": {"width_mm": 1000, "height_mm": 800}, "seed": 3,
                   "duration_s": 10, "sample_period_s": 0.1, "objects": objects,
                   "robots": [{"poses": [{"x_mm": 200, "y_mm": 400, "heading_deg": 0},
                                         {"x_mm": 800, "y_mm": 600, "heading_deg": 180}],
                               "firmware": controller}]}, f)
    out = os.path.join(WORK, name)
    shutil.rmtree(out, ignore_errors=True)
    done = subprocess.run([SIM, "-q", "--world", world, "--out", out], capture_output=True, text=True,
                          timeout=600)
    if done.returncode != 0:
        failures.append(f"{name}: exit {done.returncode}:\n{done.stderr}")
    # Each robot says its id (robot_id(): its index in the world) on its console.
    for robot in (0, 1):
        if f"e-puck {robot} here" not in done.stderr:
            failures.append(f"{name}: robot {robot} did not say its id ('e-puck {robot} here'):\n{done.stderr}")
    return out


def read(out, name):
    with open(os.path.join(out, name)) as f:
        return f.read()


os.makedirs(WORK, exist_ok=True)
host = run("host", HOST_APP)
qemu = run("qemu", qemu_controller())
if not failures:
    for name in ("trajectories.csv", "objects.csv"):
        if read(host, name) != read(qemu, name):
            failures.append(f"{name} differs between the host build ({host}) and the QEMU image ({qemu})")
    rows = list(csv.DictReader(read(qemu, "trajectories.csv").splitlines()))
    robot0 = [r for r in rows if r["robot"] == "0"]
    walked = math.dist((float(robot0[0]["x_mm"]), float(robot0[0]["y_mm"])),
                       (float(robot0[-1]["x_mm"]), float(robot0[-1]["y_mm"])))
    headings = {round(float(r["heading_deg"])) for r in robot0}
    greens = {r["led_g"] for r in rows}
    objects = list(csv.DictReader(read(qemu, "objects.csv").splitlines()))
    pushed = [o for o in objects if float(o["time_s"]) > 0 and
              math.dist((float(o["x_mm"]), float(o["y_mm"])), (600, 400)) > 1 and
              math.dist((float(o["x_mm"]), float(o["y_mm"])), (300, 600)) > 1 and
              math.dist((float(o["x_mm"]), float(o["y_mm"])), (700, 200)) > 1]
    if walked < 200 or len(headings) < 30 or greens != {"0", "3"} or not pushed:
        failures.append(f"the run shows too little: robot 0 went {walked:.0f} mm with {len(headings)} "
                        f"headings, LED green levels {sorted(greens)}, {len(pushed)} object samples moved")

for f in failures:
    print("FAIL", f)
print("ok: the QEMU image and the host build drive the same world identically" if not failures else "")
sys.exit(1 if failures else 0)
