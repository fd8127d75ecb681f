#!/usr/bin/env python3
"""--counters in the native mode, as the exact mode prints them.

    check_counters.py SIM EXACT.elf NATIVE.so

runs tests/avr/fault_ir_payload.c (robot 0 sends 150 frames, robots 1-3
print their IR driver's counters at the end; 4 robots 50 mm apart) under
--faults flip=1 with --counters 2 in both modes and checks, natively:
  a line per robot at 2 s and at 4 s (the period) and one at the end;
  the last lines' IR counters are what each robot's own report printed
  (the simulator reads them from the robot's RAM image);
  at 2 s robot 0 has sent frames and robot 1 received some: the lines
  follow the run, not only its end;
and that both modes' lines name the same counters in the same order
(their values differ: the faults' draws do), the stacks' use being
main_stack=unmeasured thread_stacks=none natively (the host's stacks).
"""
import re
import subprocess
import sys

REPORT = re.compile(r"\[robot (\d+)\] uid \d+ ((?:\w+ \d+ ?)+)")
LINE = re.compile(r"^counters t=([0-9.]+) robot=(\d+) (.*)$", re.M)


def run(sim, robot):
    done = subprocess.run([sim, "--robots", "4", "--distance", "50", "--time", "6", "--expect-stop",
                           "--faults", "flip=1,seed=3", "--fault-log", "/dev/null", "--counters", "2", robot],
                          capture_output=True, text=True, timeout=120)
    if done.returncode != 0:
        sys.exit(f"openswarm-sim failed ({done.returncode}) on {robot}:\n{done.stderr}")
    lines = [(float(t), int(r), dict(kv.split("=", 1) for kv in rest.split()))
             for t, r, rest in LINE.findall(done.stdout)]
    reports = {int(r): {k: int(v) for k, v in re.findall(r"(\w+) (\d+)", rest)}
               for r, rest in REPORT.findall(done.stdout)}
    return lines, reports


def main():
    sim, elf, so = sys.argv[1:4]
    passed = failed = 0

    def expect(ok, what):
        nonlocal passed, failed
        print(("ok   " if ok else "FAIL ") + what)
        passed, failed = passed + bool(ok), failed + (not ok)

    lines, reports = run(sim, so)
    times = sorted({t for t, _, _ in lines})
    expect(times[:2] == [2.0, 4.0] and len(times) == 3, f"lines at 2 s, 4 s and the end: {times}")
    expect(all(sorted(r for t, r, _ in lines if t == at) == [0, 1, 2, 3] for at in times),
           "each time has a line for every robot")
    last = {r: c for t, r, c in lines if t == times[-1]}
    for robot in range(4):
        own = reports.get(robot, {})
        read = {k: int(last.get(robot, {}).get("ir_" + k, -1)) for k in own if k in
                ("sent", "received", "refused", "bad_crc", "broken", "collisions", "busy")}
        expect(own and all(read[k] == own[k] for k in read),
               f"robot {robot}: the last line's IR counters {read} are its own report's")
    at_two = {r: c for t, r, c in lines if t == 2.0}
    expect(int(at_two[0]["ir_sent"]) > 0 and int(at_two[1]["ir_received"]) > 0,
           f"at 2 s robot 0 has sent {at_two[0]['ir_sent']}, robot 1 received {at_two[1]['ir_received']}")
    expect(all(c["main_stack"] == "unmeasured" and c["thread_stacks"] == "none" for _, _, c in lines),
           "natively the stacks' use is not the AVR's: unmeasured, none")
    exact, _ = run(sim, elf)
    expect(list(exact[0][2]) == list(lines[0][2]), f"the same counters in the same order as the exact mode's "
           f"({len(lines[0][2])} of them)")
    print(f"{passed} passed, {failed} failed")
    sys.exit(1 if failed else 0)


main()
