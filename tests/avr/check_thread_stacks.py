#!/usr/bin/env python3
"""Thread stacks' high-water marks from openswarm-sim --counters.

check_thread_stacks.py SIM ELF: runs thread_stacks.elf for 0.5 s and reads
the counters line at the end; thread_stacks= lists the live threads' stacks
by address, used/room each. Checks: two stacks (the ended thread's was
freed), each of 236 bytes of room (the 160 asked for, the Kilobot port's
64 extra and the 4-byte guard: 228, rounded up to 16-byte blocks: 240,
less the guard), the first (the 100-byte buffer) at least 90
bytes above the second (4 bytes), both short of their room.
"""
import re
import subprocess
import sys

sim, elf = sys.argv[1:3]
done = subprocess.run([sim, "--time", "0.5", "-q", "--counters", "0", elf],
                      capture_output=True, text=True, timeout=120)
print(done.stdout + done.stderr)
found = re.findall(r"thread_stacks=(\S+)", done.stdout)
if done.returncode != 0 or not found:
    sys.exit(f"FAIL: openswarm-sim exited {done.returncode} without a thread_stacks= counter")
stacks = [tuple(int(v) for v in s.split("/")) for s in found[-1].split(",") if s != "none"]
failed = 0


def expect(ok, what):
    global failed
    print(("ok   " if ok else "FAIL ") + what)
    failed += not ok


expect(len(stacks) == 2, f"two live thread stacks listed: {stacks}")
if len(stacks) == 2:
    (deep, deep_room), (shallow, shallow_room) = stacks
    expect(deep_room == shallow_room == 236,
           f"rooms {deep_room} and {shallow_room}: 160 + 64 + 4 bytes rounded to 16-byte blocks, less the guard")
    expect(deep >= shallow + 90, f"the thread with the 100-byte buffer used {deep} bytes, the other {shallow}")
    expect(deep < deep_room and shallow < shallow_room, "both short of their room")
sys.exit(1 if failed else 0)
