#!/usr/bin/env python3
"""The fidelity check of the e-puck in the world: the same controller
(tests/world/epuck_link_app.c: the clustering controller's camera-to-wheels
handler and a thread blinking the LEDs) drives two e-pucks among three
objects for 10 s, once built for the host (PORT epuck_world, the way the
case study runs) and once as the e-puck2 image under QEMU (board world,
ports/epuck/epuck2/qemu_world). The world's record of both runs - every
robot's pose and LEDs every 0.1 s, every object's position - must be the
same, byte for byte, and show the robots turning, pushing and blinking.
Each image's console also ends with its CPU account (cpu_account.c): the
10 s it ran, mostly asleep, with some time on the sensors and the rest.

check_epuck2_qemu_fidelity.py SIM HOST_APP QEMU_ELF QEMU_SYSTEM_ARM WORKDIR
"""
import os
import re
import stat
import sys

import epuck_fidelity

SIM, HOST_APP, QEMU_ELF, QEMU, WORK = sys.argv[1:6]
failures = []


def qemu_controller():
    """The world starts a controller as a program without arguments: a
    script that runs the image in QEMU, which reads the link from QEMU's
    standard input and answers on its standard output through semihosting,
    the robot's index in the world (OPENSWARM_ROBOT_ID) as its id."""
    path = os.path.join(WORK, "epuck2_in_qemu.sh")
    with open(path, "w") as f:
        f.write("#!/bin/sh\nexec %s -M netduinoplus2 -display none -monitor none "
                "-serial file:%s/console-$OPENSWARM_ROBOT_ID.txt "
                "-semihosting-config enable=on,target=native,arg=app,arg=--id=$OPENSWARM_ROBOT_ID "
                "-icount shift=3,align=off,sleep=off -kernel %s\n" % (QEMU, WORK, QEMU_ELF))
    os.chmod(path, os.stat(path).st_mode | stat.S_IXUSR)
    return path


def check_console(robot):
    """The image said its id and accounted for its CPU's time: at least
    the run's 10 s of virtual time, asleep for most of it, awake for some
    (the sensors' deliveries and the rest)."""
    with open(os.path.join(WORK, f"console-{robot}.txt")) as f:
        console = f.read()
    if f"e-puck {robot} here" not in console:
        failures.append(f"qemu: robot {robot} did not say its id ('e-puck {robot} here'):\n{console}")
    account = re.search(r"cpu account: robot time (\d+) us, asleep (\d+) us, sensors (\d+) us, "
                        r"other busy (\d+) us", console)
    if account is None:
        failures.append(f"qemu: robot {robot} printed no CPU account:\n{console}")
        return
    robot_us, asleep, sensors, other = (int(v) for v in account.groups())
    if robot_us < 10_000_000 or not 0.9 * robot_us < asleep < robot_us or sensors == 0 or other == 0:
        failures.append(f"qemu: robot {robot}'s CPU account does not add up: {account.group(0)}")


os.makedirs(WORK, exist_ok=True)
host = epuck_fidelity.run(SIM, WORK, "host", HOST_APP, failures)
qemu = epuck_fidelity.run(SIM, WORK, "qemu", qemu_controller(), failures, says_id=False)
if not failures:
    epuck_fidelity.compare(host, "the host build", qemu, "the QEMU image", failures)
    epuck_fidelity.shows_enough(qemu, failures)
    for robot in (0, 1):
        check_console(robot)

for f in failures:
    print("FAIL", f)
print("ok: the QEMU image and the host build drive the same world identically" if not failures else "")
sys.exit(1 if failures else 0)
