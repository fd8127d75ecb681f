#!/usr/bin/env python3
"""IR faults lose frames, never corrupt one, and every loss is counted.

check_fault_ir.py SIM ELF OUT: runs fault_ir_payload.elf on four robots 50 mm
apart, robot 0 (uid 1) sending 150 frames with a payload that follows from
each frame's sequence number, under --faults flip=0.3,cut=3 (each slot of a
frame flips at each receiver with 0.3% chance - a pulse lost or one added -
and 3% of frames are cut short), with the faults logged to OUT/faults.log,
and checks at each receiver:
  no frame delivered with a payload other than what was sent, none twice
  or out of order, and every frame the IR driver counted received reached
  the app;
  every frame sent and not delivered is counted as lost (bad_crc, broken or
  collisions): sent - received <= the losses counted;
  nothing is counted that did not happen: the losses counted exceed the
  frames lost by at most the pulses lost at that receiver (a lost pulse can
  leave a silence of 10 slots that ends a frame, whose rest then counts as
  a second broken frame);
  every frame lost had a fault logged for it (frames with a fault logged,
  grouped by time, are at least the frames lost), and the faults did lose
  frames;
then runs the same again on two threads and checks the log is the same,
byte for byte.
"""
import os
import re
import subprocess
import sys

SPEC = "flip=0.3,cut=3,seed=5"
FRAME_S = 0.0045  # a frame's length: faults within it belong to it
STATS = re.compile(r"\[robot (\d+)\] uid \d+ sent (\d+) received (\d+) refused (\d+) bad_crc (\d+) "
                   r"broken (\d+) collisions (\d+) busy \d+ delivered (\d+) corrupt (\d+) out_of_order (\d+)")


def run(sim, elf, log, threads):
    done = subprocess.run([sim, "--robots", "4", "--distance", "50", "--time", "6", "--expect-stop",
                           "--threads", str(threads), "--faults", SPEC, "--fault-log", log, elf],
                          capture_output=True, text=True, timeout=120)
    if done.returncode != 0:
        sys.exit(f"openswarm-sim failed ({done.returncode}):\n{done.stdout}\n{done.stderr}")
    return done.stdout, done.stderr


def faults_by_receiver(log):
    """Each receiver's faults: a list of (time_s, kind)."""
    faults = {}
    with open(log) as f:
        for line in f:
            fields = dict(kv.split("=", 1) for kv in line.split()[1:])
            faults.setdefault(int(fields["robot"]), []).append((float(fields["t"]), fields["kind"]))
    return faults


def frames_hit(times):
    """Faults within one frame's length of the first of a group hit one frame."""
    hit, start = 0, None
    for t in sorted(times):
        if start is None or t - start > FRAME_S:
            hit, start = hit + 1, t
    return hit


def main():
    sim, elf, out = sys.argv[1:4]
    os.makedirs(out, exist_ok=True)
    log = os.path.join(out, "faults.log")
    stdout, stderr = run(sim, elf, log, 1)
    stats = {int(m.group(1)): [int(g) for g in m.groups()[1:]] for m in STATS.finditer(stdout)}
    faults = faults_by_receiver(log)
    passed = failed = 0

    def expect(ok, what):
        nonlocal passed, failed
        print(("ok   " if ok else "FAIL ") + what)
        passed, failed = passed + ok, failed + (not ok)

    expect(sorted(stats) == [0, 1, 2, 3], f"all four robots reported ({sorted(stats)})")
    sent = stats.get(0, [0])[0]
    expect(sent == 150, f"robot 0 sent {sent} frames")
    lost_somewhere = 0
    for r in (1, 2, 3):
        _, received, refused, bad_crc, broken, collisions, delivered, corrupt, disorder = stats.get(r, [0] * 10)
        lost, counted = sent - received - refused, bad_crc + broken + collisions
        pulses_lost = sum(1 for _, kind in faults.get(r, []) if kind == "pulse-lost")
        hit = frames_hit([t for t, _ in faults.get(r, [])])
        lost_somewhere += lost
        expect(corrupt == 0 and disorder == 0, f"robot {r}: {delivered} frames delivered, {corrupt} corrupt, "
               f"{disorder} out of order")
        expect(delivered == received, f"robot {r}: the driver's {received} received all reached the app")
        expect(lost <= counted, f"robot {r}: {lost} frames lost, {counted} losses counted "
               f"(bad_crc {bad_crc}, broken {broken}, collisions {collisions})")
        expect(counted <= lost + pulses_lost, f"robot {r}: {counted} losses counted, at most the {lost} lost "
               f"plus the {pulses_lost} pulses lost")
        expect(lost <= hit, f"robot {r}: {lost} frames lost, {hit} frames with a fault logged")
    expect(lost_somewhere > 0, f"the faults lost {lost_somewhere} frames in all")
    expect(re.search(r"faults injected: 0 reset, 0 brownout, \d+ pulse-lost, \d+ pulse-added, \d+ frame-cut", stderr)
           is not None, "the run's summary counts the faults")

    first = open(log).read()
    run(sim, elf, log, 2)
    expect(open(log).read() == first, "two threads inject the same faults at the same times")
    print(f"{passed} passed, {failed} failed")
    sys.exit(1 if failed else 0)


main()
