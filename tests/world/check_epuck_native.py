#!/usr/bin/env python3
"""The native mode's e-pucks against the pipe mode's: the same controller
(tests/world/epuck_link_app.c: the clustering controller's camera-to-wheels
handler and a thread blinking the LEDs) drives two e-pucks among three
objects for 10 s, once as one process per robot over a pipe (PORT
epuck_world) and once loaded into the simulator (the same sources built
natively, board epuck_world). The pipe mode is deterministic for a seed,
so the world's records of both runs must be the same, byte for byte. And
the case study's plain loop (templates/object-clustering/plain), natively,
must drive the robots too.

check_epuck_native.py SIM PIPE_APP NATIVE_APP NATIVE_PLAIN WORKDIR
"""
import os
import sys

import epuck_fidelity

SIM, PIPE_APP, NATIVE_APP, NATIVE_PLAIN, WORK = sys.argv[1:6]
failures = []

os.makedirs(WORK, exist_ok=True)
pipe = epuck_fidelity.run(SIM, WORK, "pipe", PIPE_APP, failures)
native = epuck_fidelity.run(SIM, WORK, "native", NATIVE_APP, failures)
if not failures:
    epuck_fidelity.compare(pipe, "the pipe mode", native, "the native mode", failures)
    epuck_fidelity.shows_enough(native, failures)
plain = epuck_fidelity.run(SIM, WORK, "plain", NATIVE_PLAIN, failures, says_id=False)
if not failures:
    epuck_fidelity.shows_enough(plain, failures, blinks=False)

# A world that asks for the native mode refuses a controller built for the
# pipe mode: exit 2, the world, the program and the fix.
refused = []
epuck_fidelity.run(SIM, WORK, "asks_native", PIPE_APP, refused, seconds=1, says_id=False, fidelity="native")
if not (len(refused) == 1 and "exit 2:" in refused[0] and "asks_native.json asks for \"fidelity\": \"native\"" in refused[0]
        and "openswarm build --native" in refused[0]):
    failures.append(f"a pipe-mode controller in a native world was not refused as it should be: {refused}")

for f in failures:
    print("FAIL", f)
print("ok: the native mode drives the world as the pipe mode does" if not failures else "")
sys.exit(1 if failures else 0)
