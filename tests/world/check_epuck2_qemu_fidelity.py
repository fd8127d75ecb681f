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
import os
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
                "-serial file:/dev/stderr "
                "-semihosting-config enable=on,target=native,arg=app,arg=--id=$OPENSWARM_ROBOT_ID "
                "-icount shift=3,align=off,sleep=off -kernel %s\n" % (QEMU, QEMU_ELF))
    os.chmod(path, os.stat(path).st_mode | stat.S_IXUSR)
    return path


os.makedirs(WORK, exist_ok=True)
host = epuck_fidelity.run(SIM, WORK, "host", HOST_APP, failures)
qemu = epuck_fidelity.run(SIM, WORK, "qemu", qemu_controller(), failures)
if not failures:
    epuck_fidelity.compare(host, "the host build", qemu, "the QEMU image", failures)
    epuck_fidelity.shows_enough(qemu, failures)

for f in failures:
    print("FAIL", f)
print("ok: the QEMU image and the host build drive the same world identically" if not failures else "")
sys.exit(1 if failures else 0)
