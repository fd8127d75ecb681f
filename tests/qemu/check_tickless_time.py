#!/usr/bin/env python3
"""qemu.tickless_time: the same image built with the periodic tick and with
tickless idle prints the same times (tests/qemu/tickless_time.c). Only two
lines may differ: the tick interrupts taken (tickless must take under a
tenth of the ticking build's) and how far the tick grid moved in QEMU's
virtual time (at most MAX_GRID_MOVE 100-ns counts apart: a tick is 10000).
QEMU's SysTick loses about 1.2 ns at each reload (its period's fraction of
a nanosecond), so the ticking build's grid falls 15 us behind in 12.7 s;
the tickless build, with 25 times fewer reloads, about 2 us: the two
differ by that, not by the tick's re-phasing after an interrupt.

    check_tickless_time.py TICKING.elf TICKLESS.elf QEMU-COMMAND...
"""
import re
import subprocess
import sys

MAX_GRID_MOVE = 300  # 30 us of virtual time; a tick is 1 ms of it
VARIABLE = re.compile(r"^(tick interrupts|the grid moved by) (-?\d+)$")


def run(qemu, image):
    out = subprocess.run(qemu + ["-kernel", image], capture_output=True, text=True, timeout=300)
    if out.returncode != 0:
        sys.exit(f"{image}: QEMU exited with status {out.returncode}\n{out.stdout}{out.stderr}")
    lines = [l.rstrip("\r") for l in out.stdout.splitlines() if l.strip()]
    fixed = [l for l in lines if not VARIABLE.match(l)]
    variable = {m.group(1): int(m.group(2)) for m in map(VARIABLE.match, lines) if m}
    if set(variable) != {"tick interrupts", "the grid moved by"}:
        sys.exit(f"{image}: the run did not reach its end:\n{out.stdout}")
    return fixed, variable


def main():
    ticking_image, tickless_image, qemu = sys.argv[1], sys.argv[2], sys.argv[3:]
    ticking, ticking_numbers = run(qemu, ticking_image)
    tickless, tickless_numbers = run(qemu, tickless_image)
    print("\n".join(tickless))
    print(f"tick interrupts: ticking {ticking_numbers['tick interrupts']}, tickless {tickless_numbers['tick interrupts']}")
    print(f"grid moved (100 ns): ticking {ticking_numbers['the grid moved by']}, "
          f"tickless {tickless_numbers['the grid moved by']}")
    failures = []
    if ticking != tickless:
        diff = [f"  ticking: {a!r}\n  tickless: {b!r}" for a, b in zip(ticking, tickless) if a != b]
        failures.append("the times differ between the builds:\n" + "\n".join(diff or ["  (line counts differ)"]))
    if tickless_numbers["tick interrupts"] * 10 >= ticking_numbers["tick interrupts"]:
        failures.append("tickless idle took at least a tenth of the ticking build's tick interrupts")
    moved = abs(tickless_numbers["the grid moved by"] - ticking_numbers["the grid moved by"])
    if moved > MAX_GRID_MOVE:
        failures.append(f"the tick grid moved by {moved} x 100 ns more than the ticking build's (at most {MAX_GRID_MOVE})")
    if failures:
        sys.exit("\n".join(failures))
    print("same times, tickless idle")


if __name__ == "__main__":
    main()
