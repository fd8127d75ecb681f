#!/usr/bin/env python3
"""The case study's OpenSwarm arm as shipped: the object-clustering
template's own app (templates/object-clustering/main.c and what `openswarm
build` generates from its openswarm.json), built by the tool for the host
(PORT epuck_world) and as the e-puck2 image under QEMU (board world), drives
the fidelity check's world (two e-pucks among three objects for 10 s): the
world's records must be the same byte for byte and show the robots turning
and pushing. Each image's CPU account must show the kernel's robot: asleep
most of the time, awake for the camera's frames and the rest, with the
port's default tick (tickless idle).

check_epuck2_qemu_template.py SIM HOST_APP QEMU_ELF QEMU_SYSTEM_ARM WORKDIR
"""
import sys

import epuck_fidelity

work, failures = epuck_fidelity.host_against_qemu(sys.argv, blinks=False)
if not failures:
    for robot in (0, 1):
        epuck_fidelity.kernel_account(work, robot, failures)
sys.exit(epuck_fidelity.report(failures, "ok: the template's QEMU image and its host build drive the same world "
                                         "identically"))
