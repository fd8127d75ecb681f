#!/usr/bin/env python3
"""Issue 15's budget for classic Kilobot programs on our kilolib, as
docs/benchmarks.md states it: a printf-free program within 1.5 KB of the
classic library's 6.4 KB of flash (at most 7900 bytes: .text + .data) and
in at most 450 bytes of RAM (.data + .bss + .noinit, every stack but
main's). The e2e test holds the template to the same; this holds the lab
programs the page lists, so a kernel change that outgrows one fails here.

    check_kilolib_budget.py ELF...
"""
import subprocess
import sys

FLASH_MAX = 6400 + 1500
RAM_MAX = 450


def sections(elf):
    out = subprocess.run(["avr-size", "-A", elf], check=True, capture_output=True, text=True).stdout
    found = {}
    for line in out.splitlines():
        fields = line.split()
        if len(fields) >= 2 and fields[1].isdigit():
            found[fields[0]] = int(fields[1])
    return found


def main(elves):
    failed = 0
    for elf in elves:
        s = sections(elf)
        flash = s.get(".text", 0) + s.get(".data", 0)
        ram = s.get(".data", 0) + s.get(".bss", 0) + s.get(".noinit", 0)
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
