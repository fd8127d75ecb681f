"""The e-puck fidelity checks' common part (check_epuck2_qemu_fidelity.py,
check_epuck_native.py): one small world - two e-pucks among three objects
for 10 s, every pose and LED every 0.1 s - run with a given controller,
the records of two runs compared byte for byte, and the run checked to
show the robots turning, pushing and blinking."""
import csv
import json
import math
import os
import re
import shutil
import stat
import subprocess

OBJECTS = ((600, 400), (300, 600), (700, 200))


def run(sim, work, name, controller, failures, seconds=10, says_id=True, fidelity=None):
    """The world with controller on both robots, its outputs' folder."""
    world = os.path.join(work, name + ".json")
    objects = [{"x_mm": x, "y_mm": y, "radius_mm": 50, "mass_g": 50, "friction": 0.5} for x, y in OBJECTS]
    with open(world, "w") as f:
        json.dump({"robot": "epuck", "arena": {"width_mm": 1000, "height_mm": 800}, "seed": 3,
                   "duration_s": seconds, "sample_period_s": 0.1, "objects": objects,
                   "robots": [{"poses": [{"x_mm": 200, "y_mm": 400, "heading_deg": 0},
                                         {"x_mm": 800, "y_mm": 600, "heading_deg": 180}],
                               "firmware": controller}]} | ({"fidelity": fidelity} if fidelity else {}), f)
    out = os.path.join(work, name)
    shutil.rmtree(out, ignore_errors=True)
    done = subprocess.run([sim, "-q", "--world", world, "--out", out], capture_output=True, text=True,
                          timeout=600)
    if done.returncode != 0:
        failures.append(f"{name}: exit {done.returncode}:\n{done.stderr}")
    # Each robot says its id (robot_id(): its index in the world) on its console.
    for robot in (0, 1) if says_id else ():
        if f"e-puck {robot} here" not in done.stderr + done.stdout:
            failures.append(f"{name}: robot {robot} did not say its id ('e-puck {robot} here'):\n{done.stderr}")
    return out


def qemu_controller(qemu, image, work):
    """The world starts a controller as a program without arguments: a
    script that runs the e-puck2 image in QEMU, which reads the link from
    QEMU's standard input and answers on its standard output through
    semihosting, the robot's index in the world (OPENSWARM_ROBOT_ID) as its
    id, its console in work/console-ID.txt."""
    path = os.path.join(work, "epuck2_in_qemu.sh")
    with open(path, "w") as f:
        f.write("#!/bin/sh\nexec %s -M netduinoplus2 -display none -monitor none "
                "-serial file:%s/console-$OPENSWARM_ROBOT_ID.txt "
                "-semihosting-config enable=on,target=native,arg=app,arg=--id=$OPENSWARM_ROBOT_ID "
                "-icount shift=3,align=off,sleep=off -kernel %s\n" % (qemu, work, image))
    os.chmod(path, os.stat(path).st_mode | stat.S_IXUSR)
    return path


def cpu_account(work, robot, failures):
    """Robot's CPU account from its console (us: robot time, asleep,
    sensors, other busy), None after a failure if it printed none."""
    with open(os.path.join(work, f"console-{robot}.txt")) as f:
        console = f.read()
    account = re.search(r"cpu account: robot time (\d+) us, asleep (\d+) us, sensors (\d+) us, "
                        r"other busy (\d+) us", console)
    if account is None:
        failures.append(f"qemu: robot {robot} printed no CPU account:\n{console}")
        return None
    return [int(v) for v in account.groups()], console


def host_against_qemu(argv, blinks):
    """argv's SIM HOST_PROGRAM QEMU_ELF QEMU_SYSTEM_ARM WORKDIR: the
    controller's host build and its QEMU image drive the world, whose
    records must be the same and show enough (shows_enough). The work
    folder and the failures."""
    sim, host_program, image, qemu, work = argv[1:6]
    failures = []
    os.makedirs(work, exist_ok=True)
    host = run(sim, work, "host", host_program, failures, says_id=False)
    image_out = run(sim, work, "qemu", qemu_controller(qemu, image, work), failures, says_id=False)
    if not failures:
        compare(host, "the host build", image_out, "the QEMU image", failures)
        shows_enough(image_out, failures, blinks=blinks)
    return work, failures


def report(failures, success):
    """Each failure, or success; the exit status."""
    for f in failures:
        print("FAIL", f)
    print(success if not failures else "")
    return 1 if failures else 0


def account_tick(console):
    """The tick the account line says the robot ran with (tickless idle,
    periodic, none), None if it says none."""
    tick = re.search(r"^cpu account: .*, tick ([a-z ]+)$", console, re.M)
    return tick.group(1) if tick else None


def kernel_account(work, robot, failures):
    """Robot's CPU account must be a kernel's robot's: at least the run's
    10 s of virtual time, asleep for most of it, awake for some (the
    sensors' deliveries and the rest), with the port's default tick
    (tickless idle). Its console, None if it printed no account."""
    found = cpu_account(work, robot, failures)
    if found is None:
        return None
    (robot_us, asleep, sensors, other), console = found
    if robot_us < 10_000_000 or not 0.9 * robot_us < asleep < robot_us or sensors == 0 or other == 0:
        failures.append(f"qemu: robot {robot}'s CPU account does not add up: {robot_us} us robot time, "
                        f"{asleep} asleep, {sensors} on the sensors, {other} else awake")
    if account_tick(console) != "tickless idle":
        failures.append(f"qemu: robot {robot} says it ran with tick {account_tick(console)}, not the Cortex-M4 "
                        "port's default, tickless idle")
    return console


def read(out, name):
    with open(os.path.join(out, name)) as f:
        return f.read()


def compare(a, a_name, b, b_name, failures):
    """The two runs' records, byte for byte."""
    for name in ("trajectories.csv", "objects.csv"):
        if read(a, name) != read(b, name):
            failures.append(f"{name} differs between {a_name} ({a}) and {b_name} ({b})")


def shows_enough(out, failures, blinks=True):
    """Robot 0 went somewhere turning, an object moved, the LEDs blinked."""
    rows = list(csv.DictReader(read(out, "trajectories.csv").splitlines()))
    robot0 = [r for r in rows if r["robot"] == "0"]
    walked = math.dist((float(robot0[0]["x_mm"]), float(robot0[0]["y_mm"])),
                       (float(robot0[-1]["x_mm"]), float(robot0[-1]["y_mm"])))
    headings = {round(float(r["heading_deg"])) for r in robot0}
    greens = {r["led_g"] for r in rows}
    objects = list(csv.DictReader(read(out, "objects.csv").splitlines()))
    pushed = [o for o in objects if float(o["time_s"]) > 0 and
              all(math.dist((float(o["x_mm"]), float(o["y_mm"])), at) > 1 for at in OBJECTS)]
    if walked < 200 or len(headings) < 30 or (blinks and greens != {"0", "3"}) or not pushed:
        failures.append(f"the run shows too little: robot 0 went {walked:.0f} mm with {len(headings)} "
                        f"headings, LED green levels {sorted(greens)}, {len(pushed)} object samples moved")
