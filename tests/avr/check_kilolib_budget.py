#!/usr/bin/env python3
"""Issue 15's budget for classic Kilobot programs on our kilolib, as
docs/benchmarks.md states it: a printf-free program within 1.5 KB of the
classic library's 6.4 KB of flash (at most 7900 bytes: .text + .data) and
in at most 450 bytes of RAM (.data + .bss + .noinit, every stack but
main's). The e2e test holds the template to the same; this holds the lab
programs the page lists, so a kernel change that outgrows one fails here.

    check_kilolib_budget.py ELF...
"""
import os
import sys

# The figures docs/benchmarks.md's table shows, by the same definition
# (imported without leaving a bytecode cache in the source tree).
sys.dont_write_bytecode = True
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "bench"))
from kilolib_cost import sizes  # noqa: E402

FLASH_MAX = 6400 + 1500
RAM_MAX = 450


def main(elves):
    failed = 0
    for elf in elves:
        flash, ram = sizes(elf)
        ok = flash <= FLASH_MAX and ram <= RAM_MAX
        failed += not ok
        print(f"{'ok  ' if ok else 'OVER'} {elf}: flash {flash} B (at most {FLASH_MAX}), "
              f"RAM {ram} B (at most {RAM_MAX})")
    if failed:
        print(f"{failed} program(s) over kilolib's budget: make the kernel smaller where the "
              "system thread runs alone (kilolib_pools.h), or say why in docs/benchmarks.md")
    print(f"{len(elves) - failed} passed, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit("usage: check_kilolib_budget.py ELF...")
    sys.exit(main(sys.argv[1:]))
