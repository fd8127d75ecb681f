#!/usr/bin/env python3
"""The case study's OpenSwarm arm as shipped: the object-clustering
template's own app (templates/object-clustering/main.c and what `openswarm
build` generates from its openswarm.json), built by the tool for the host
(PORT epuck_world) and as the e-puck2 image under QEMU (board world), drives
the fidelity check's world (two e-pucks among three objects for 10 s): the
world's records must be the same byte for byte and show the robots turning
and pushing. Each image's CPU account must show the kernel's robot: asleep
most of the time, awake for the camera's frames and the rest.

check_epuck2_qemu_template.py SIM HOST_APP QEMU_ELF QEMU_SYSTEM_ARM WORKDIR
"""
import os
import sys

import epuck_fidelity

SIM, HOST_APP, QEMU_ELF, QEMU, WORK = sys.argv[1:6]
failures = []

os.makedirs(WORK, exist_ok=True)
host = epuck_fidelity.run(SIM, WORK, "host", HOST_APP, failures, says_id=False)
qemu = epuck_fidelity.run(SIM, WORK, "qemu", epuck_fidelity.qemu_controller(QEMU, QEMU_ELF, WORK), failures,
                          says_id=False)
if not failures:
    epuck_fidelity.compare(host, "the host build", qemu, "the QEMU image", failures)
    epuck_fidelity.shows_enough(qemu, failures, blinks=False)
    for robot in (0, 1):
        epuck_fidelity.kernel_account(WORK, robot, failures)

for f in failures:
    print("FAIL", f)
print("ok: the template's QEMU image and its host build drive the same world identically" if not failures else "")
sys.exit(1 if failures else 0)
