#!/usr/bin/env python3
"""IR between robots whose clocks differ (--faults drift): decoded within
the receiver's tolerance, lost and counted past it, never corrupted.

check_drift_ir.py SIM ELF OUT: fault_ir_payload.elf on four robots 50 mm
apart, robot 0 (uid 1) sending 150 frames whose payload follows from their
sequence number, its clock drifted by D% (drift:0=D) for D in +-2, +-4,
+-5, +-8, the receivers undrifted. Checks at each receiver: within 4%
every frame is delivered (the receiver resyncs on each byte's start bit);
at 5% and 8% frames are lost (at 5% some decode into wrong bits, which the
CRC catches) and every loss is counted as bad_crc, broken or collisions;
never a frame delivered corrupt, twice or out of order; the fault log has
each drift.
"""
import os
import re
import subprocess
import sys

STATS = re.compile(r"\[robot (\d+)\] uid \d+ sent (\d+) received (\d+) refused (\d+) bad_crc (\d+) "
                   r"broken (\d+) collisions (\d+) busy \d+ delivered (\d+) corrupt (\d+) out_of_order (\d+)")
TOLERATED_PCT = 4

sim, elf, out = sys.argv[1:4]
os.makedirs(out, exist_ok=True)
failed = 0


def expect(ok, what):
    global failed
    print(("ok   " if ok else "FAIL ") + what)
    failed += not ok


def run(spec, log):
    done = subprocess.run([sim, "--robots", "4", "--distance", "50", "--time", "6", "--expect-stop",
                           "--faults", spec, "--fault-log", log, elf],
                          capture_output=True, text=True, timeout=240)
    if done.returncode != 0:
        sys.exit(f"openswarm-sim failed ({done.returncode}):\n{done.stdout}\n{done.stderr}")
    return {int(m.group(1)): [int(g) for g in m.groups()[1:]] for m in STATS.finditer(done.stdout)}


for pct in (2, -2, 4, -4, 5, -5, 8, -8):
    log = os.path.join(out, f"faults_{pct:+d}.log")
    stats = run(f"drift:0={pct}", log)
    expect(open(log).read().startswith(f"fault t=0.000000 robot=0 kind=clock-drift ppm={pct * 10000:+d} "),
           f"sender {pct:+d}%: the fault log has the drift")
    sent = stats.get(0, [0])[0]
    expect(sent == 150, f"sender {pct:+d}%: robot 0 sent {sent} frames")
    for r in (1, 2, 3):
        _, received, refused, bad_crc, broken, collisions, delivered, corrupt, disorder = stats.get(r, [0] * 10)
        lost, counted = sent - received - refused, bad_crc + broken + collisions
        expect(corrupt == 0 and disorder == 0 and delivered == received,
               f"sender {pct:+d}%, robot {r}: {delivered} delivered, {corrupt} corrupt, {disorder} out of order")
        if abs(pct) <= TOLERATED_PCT:
            expect(delivered == sent, f"sender {pct:+d}%, robot {r}: all {sent} frames delivered")
        else:
            expect(0 < lost <= counted, f"sender {pct:+d}%, robot {r}: {lost} frames lost, {counted} losses counted "
                   f"(bad_crc {bad_crc}, broken {broken}, collisions {collisions})")
sys.exit(1 if failed else 0)
