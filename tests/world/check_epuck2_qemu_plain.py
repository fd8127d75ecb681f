#!/usr/bin/env python3
"""The case study's plain loop (templates/object-clustering/plain: no OS)
as its host build and as the e-puck2 image under QEMU (no kernel started,
ports/epuck/epuck2/qemu_world/plain_world_qemu.c) drives the fidelity
check's world (two e-pucks among three objects for 10 s): the world's
records must be the same byte for byte and show the robots turning and
pushing. Each image's CPU account must show a program that never sleeps
(no idle thread) and did work, and no tick (its kernel never started).

check_epuck2_qemu_plain.py SIM HOST_PLAIN QEMU_ELF QEMU_SYSTEM_ARM WORKDIR
"""
import sys

import epuck_fidelity

WORK, failures = epuck_fidelity.host_against_qemu(sys.argv, blinks=False)
if not failures:
    for robot in (0, 1):
        found = epuck_fidelity.cpu_account(WORK, robot, failures)
        if found is not None:
            robot_us, asleep, sensors, program = found[0]
            if asleep != 0 or sensors != 0 or program == 0:
                failures.append(f"qemu: robot {robot}'s CPU account is not a plain loop's: {robot_us} us robot "
                                f"time, {asleep} asleep, {sensors} on the sensors, {program} the program's")
            if epuck_fidelity.account_tick(found[1]) != "none":
                failures.append(f"qemu: robot {robot} (no kernel started) says it ran with tick "
                                f"{epuck_fidelity.account_tick(found[1])}, not none")

sys.exit(epuck_fidelity.report(failures, "ok: the plain loop's QEMU image and host build drive the same world "
                                         "identically"))
