#!/usr/bin/env python3
"""IR faults on whole frames: the share of frames --faults flip=PCT and
cut=PCT lose in the exact mode (pulses lost and added in slots, decoded by
the firmware) and in the native mode (the same faults drawn on the frame's
slots, the pulses left replayed through the same decoder:
sim/src/native/native_frame_faults.c), beside what "any flipped slot loses
the frame" would predict, 1 - (1 - p)^130. tests/avr/fault_ir_payload.c:
robot 0 sends 150 frames to three receivers 50 mm away; seeds 1-6, so 18
receivers a point. Also how the receivers counted what they lost (bad CRC,
broken, collided) and whether any frame was delivered corrupt. Rewrites
its section of docs/benchmarks.md.

    python3 bench/fault_frames.py    # uses build/ (ctest's build: openswarm-sim,
                                     # tests/avr's fault_ir_payload.elf, native_fault_ir_payload);
                                     # about 2 minutes on 2 cores
"""
import os
import statistics
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "bench"))
sys.path.insert(0, os.path.join(ROOT, "tests", "native"))
import benchmarks_page  # noqa: E402
import crosscheck_faults  # noqa: E402

BUILD = os.path.join(ROOT, "build")
SIM = os.path.join(BUILD, "sim", "openswarm-sim")
EXACT = os.path.join(BUILD, "tests", "avr", "fault_ir_payload.elf")
NATIVE = os.path.join(BUILD, "tests", "native", "native_fault_ir_payload.so")
OUT = os.path.join(BUILD, "bench", "fault_frames")
SPECS = ("flip=0.1", "flip=0.3", "flip=1", "flip=3", "cut=10", "cut=50")
SEEDS = range(1, 7)
SLOTS = 130
COMMAND = "python3 bench/fault_frames.py"
BEGIN, END = "<!-- fault_frames: begin -->", "<!-- fault_frames: end -->"


def measure(robot, mode, spec):
    """Every receiver's counters over the seeds."""
    return [r for s in SEEDS
            for r in crosscheck_faults.receivers(SIM, robot, OUT, f"{mode}-{spec}-{s}", f"{spec},seed={s}")]


def share_lost(receivers):
    lost = [1 - r["received"] / crosscheck_faults.FRAMES for r in receivers]
    return f"{100 * statistics.mean(lost):.1f} +- {100 * statistics.stdev(lost):.1f}"


def causes(receivers):
    total = {k: sum(r[k] for r in receivers) for k in ("bad_crc", "broken", "collisions", "corrupt")}
    return f"{total['bad_crc']} / {total['broken']} / {total['collisions']}; {total['corrupt']}"


def main():
    rows = []
    for spec in SPECS:
        kind, pct = spec.split("=")
        p = float(pct) / 100
        naive = 1 - (1 - p) ** SLOTS if kind == "flip" else p
        exact, native = measure(EXACT, "exact", spec), measure(NATIVE, "native", spec)
        rows.append(f"| `{spec}` | {share_lost(exact)} | {share_lost(native)} | {100 * naive:.1f} | "
                    f"{causes(exact)} | {causes(native)} |")
        print(rows[-1], flush=True)
    load = os.getloadavg()[0]
    section = "\n".join([
        BEGIN,
        f"Measured with `{COMMAND}` (load {load:.1f} at the end): `tests/avr/fault_ir_payload.c`, robot 0 "
        f"sending 150 frames to three receivers 50 mm away, seeds 1-{SEEDS[-1]} (18 receivers a point); "
        "the share of the frames each receiver lost, mean +- sd over the receivers, in %.",
        "",
        "| faults | exact, lost % | native, lost % | 1 - (1 - p)^130 (flip), p (cut) | exact: bad CRC / broken / "
        "collided; corrupt | native: the same |",
        "|---|---:|---:|---:|---|---|",
        *rows,
        END,
    ])
    benchmarks_page.write_section(BEGIN, END, section)


main()
