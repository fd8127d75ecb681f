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
import sys

import epuck_fidelity

SIM, HOST_APP, QEMU_ELF, QEMU, WORK = sys.argv[1:6]
failures = []


def check_console(robot):
    """The image said its id and accounted for its CPU's time as a
    kernel's robot."""
    console = epuck_fidelity.kernel_account(WORK, robot, failures)
    if console is not None and f"e-puck {robot} here" not in console:
        failures.append(f"qemu: robot {robot} did not say its id ('e-puck {robot} here'):\n{console}")


os.makedirs(WORK, exist_ok=True)
host = epuck_fidelity.run(SIM, WORK, "host", HOST_APP, failures)
qemu = epuck_fidelity.run(SIM, WORK, "qemu", epuck_fidelity.qemu_controller(QEMU, QEMU_ELF, WORK), failures,
                          says_id=False)
if not failures:
    epuck_fidelity.compare(host, "the host build", qemu, "the QEMU image", failures)
    epuck_fidelity.shows_enough(qemu, failures)
    for robot in (0, 1):
        check_console(robot)

for f in failures:
    print("FAIL", f)
print("ok: the QEMU image and the host build drive the same world identically" if not failures else "")
sys.exit(1 if failures else 0)
