#!/usr/bin/env python3
"""In a world each robot's analog inputs carry its own noise: classic
rand_hard() (the temperature sensor's lowest bits) and the rand_soft()
seeded from it give every robot its own numbers, and the same ones again
on a second run. check_random.py SIM ELF WORLD"""
import re
import subprocess
import sys

sim, elf, world = sys.argv[1:4]


def numbers():
    done = subprocess.run([sim, "--world", world, elf], capture_output=True, text=True, timeout=120)
    if done.returncode != 0:
        sys.exit(f"openswarm-sim failed ({done.returncode}):\n{done.stderr}")
    found = re.findall(r"robot (\d+) hard (\d+ \d+ \d+) soft (\d+ \d+ \d+)", done.stdout)
    return {uid: (hard, soft) for uid, hard, soft in found}


first, second = numbers(), numbers()
checks = {
    "every robot printed its numbers": len(first) == 5,
    "rand_hard differs from robot to robot": len({h for h, _ in first.values()}) == len(first),
    "rand_soft differs from robot to robot": len({s for _, s in first.values()}) == len(first),
    "a second run gives the same numbers": first == second,
}
for what, ok in checks.items():
    print(("ok   " if ok else "FAIL ") + what)
print(first)
failed = sum(not ok for ok in checks.values())
print(f"{len(checks) - failed} passed, {failed} failed")
sys.exit(1 if failed else 0)
