#!/usr/bin/env python3
"""The soak run (docs/reliability.md, "Soak run"): 50 Kilobots running the
gradient template's program in bench/worlds/soak.json for an hour of
simulated time, with faults injected, every robot's counters read at every
quarter (openswarm-sim --counters), and a check that nothing
grows without bound.

    python3 bench/soak.py [--minutes 60] [--out soak-out] [--build build]

Checks, printed as ok/FAIL lines, exit status 1 if any fails:
  no robot's firmware reported a stack overflow, a CPU fault, a critical
  section left open or a handler overrun, and none crashed or hung;
  peaks are bounded: the highest event queue peak, main stack and thread
  stack worst use of any robot rose in the second half at most as much as
  from the first quarter to half time (a high-water mark of rare
  coincidences of interrupts and messages rises ever more slowly, by about
  as much each time the run doubles; a leak rises with the time);
  counters never go down between half time and the end for robots without
  a reset in between (a counter that wrapped would), and a counter at
  65535 (saturated: it stops there) is reported;
  the main stack and no thread stack ever reaches its room;
  no counter's rate grows: over the robots not reset within each interval
  (scaled to their number), what each counter gains in the last quarter is
  at most what it gained in the second (the
  first holds the gradient's forming, when robots start talking) plus
  three standard deviations of a Poisson count (3 sqrt(n)) plus 5 (faults
  come at random: a rate that merely fluctuates passes, one that climbs
  does not); a counter of what an injected fault breaks (ir_broken: cut
  frames) may rise as much as the faults its robots received did.
Writes OUT/counters.txt (every robot's counters, at each quarter), OUT/faults.log
(one line per injected fault) and OUT/summary.txt (totals and the checks).
Not part of CI: an hour of 50 robots takes hours of wall time.
"""
import argparse
import os
import subprocess
import sys
import time
from collections import defaultdict

FAULTS = "reset=2,brownout=1,brownout-ms=50,flip=0.05,cut=0.5,blank=2,drift=2,seed=1"
PEAKS = ("event_queue_peak", "main_stack_used", "thread_stack_used")
# Stacks' sizes, not counters: no rate is compared for them.
NOT_COUNTERS = PEAKS + ("main_stack_room", "thread_stack_room")
NEVER = ("stack_overflows", "cpu_faults", "critical_leaks", "handler_overruns")
# Counters that count what injected faults break, and the fault that does it
# most: a cut frame is broken (and its rest may be counted again).
DRIVEN_BY = {"ir_broken": "frame-cut"}


def parse_counters(path):
    """{time: {robot: {key: value}}} from the --counters lines."""
    samples = defaultdict(dict)
    with open(path) as f:
        for line in f:
            if not line.startswith("counters "):
                continue
            fields = dict(kv.split("=", 1) for kv in line.split()[1:])
            t, robot = float(fields.pop("t")), int(fields.pop("robot"))
            used, _, room = fields.pop("main_stack").partition("/")
            # thread_stacks=USED/ROOM,...: the deepest use of any thread's, and
            # how close any came to its room (room - used at least)
            stacks = [tuple(map(int, t.split("/"))) for t in fields.pop("thread_stacks", "none").split(",")
                      if t != "none"]
            values = {k: int(v) for k, v in fields.items() if v.isdigit()}
            values["main_stack_used"], values["main_stack_room"] = int(used), int(room or 0)
            values["thread_stack_used"] = max((u for u, _ in stacks), default=0)
            values["thread_stack_room"] = min((r - u for u, r in stacks), default=1)
            samples[t][robot] = values
    return samples


def faults_received(log):
    """{robot: {kind: [times]}} of the faults injected into what each robot received."""
    times = defaultdict(lambda: defaultdict(list))
    with open(log) as f:
        for line in f:
            fields = dict(kv.split("=", 1) for kv in line.split()[1:])
            times[int(fields["robot"])][fields["kind"]].append(float(fields["t"]))
    return times


def restarted(log):
    """{robot: [times]} of resets and brown-outs."""
    times = defaultdict(list)
    with open(log) as f:
        for line in f:
            fields = dict(kv.split("=", 1) for kv in line.split()[1:])
            if fields["kind"] in ("reset", "brownout"):
                times[int(fields["robot"])].append(float(fields["t"]))
    return times


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    args = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    args.add_argument("--minutes", type=float, default=60.0, help="simulated minutes (default 60)")
    args.add_argument("--out", default="soak-out", help="folder for the outputs (default soak-out)")
    args.add_argument("--build", default=os.path.join(here, "..", "build"), help="the build folder")
    args.add_argument("--check-only", action="store_true", help="check OUT's files of an earlier run again (one cut short: on the "
                      "three quarters or more it has)")
    a = args.parse_args()
    sim = os.path.join(a.build, "sim", "openswarm-sim")
    elf = os.path.join(a.build, "tests", "avr", "world_gradient.elf")
    for path in (sim, elf):
        if not os.path.exists(path):
            sys.exit(f"soak.py: {path} is missing: build it first (cmake --build {a.build} --target "
                     f"openswarm-sim avr_firmware)")
    os.makedirs(a.out, exist_ok=True)
    seconds = a.minutes * 60.0
    counters, log = os.path.join(a.out, "counters.txt"), os.path.join(a.out, "faults.log")
    command = [sim, "--world", os.path.join(here, "worlds", "soak.json"), "--time", f"{seconds:g}", "-q",
               "--no-progress", "--faults", FAULTS, "--fault-log", log, "--counters", f"{seconds / 4:g}", elf]
    lines, failed = [], False
    if not a.check_only:
        print("running:", " ".join(command), flush=True)
        start = time.monotonic()
        with open(counters, "w") as out:
            done = subprocess.run(command, stdout=out, stderr=subprocess.PIPE, text=True)
        wall = time.monotonic() - start
        lines = [f"{a.minutes:g} min of simulated time, 50 robots, in {wall / 60:.1f} min of wall time "
                 f"({seconds / wall:.3f}x real time); exit status {done.returncode}", done.stderr.strip()]
        failed = done.returncode != 0

    def expect(ok, what):
        nonlocal failed
        lines.append(("ok   " if ok else "FAIL ") + what)
        failed |= not ok

    samples = parse_counters(counters)
    # Every quarter; a run cut short (killed) has fewer: from three on, the
    # checks use what there is (the second sample as the half, the last
    # two as the last quarter).
    times = sorted(samples)
    if len(times) < 3:
        sys.exit(f"soak.py: expected counters at three quarters of the run at least in {counters}")
    quarter, half, three_quarters, end = times[0], times[1], times[-2], times[-1]
    if len(times) < 4:
        lines.append(f"the run was cut short: counters at {', '.join(f'{t:g}' for t in times)} s")
    restarts = restarted(log)
    robots = sorted(samples[end])
    for key in NEVER:
        worst = max(samples[end][r].get(key, 0) for r in robots)
        expect(worst == 0, f"{key}: {worst} at worst")
    # The robots that ran an interval through: not reset or browned out
    # within it (over an hour nearly every robot is reset some time, so
    # "never reset at all" leaves none).
    def steady(since, until):
        return [r for r in robots if r in samples[since] and r in samples[until]
                and not any(since < t <= until for t in restarts.get(r, []))]

    # A peak (a high-water mark) only rises. The highest of rare
    # coincidences of interrupts and messages rises ever more slowly, by
    # about as much each time the run doubles; a leak rises with the time.
    # So the top over all robots may rise in the second half at most as
    # much as it did in the quarter before. How many robots that ran the
    # second half without a reset still rose in its last quarter is shown.
    kept_running = steady(half, end)
    for key in PEAKS:
        top = [max(samples[t][r][key] for r in samples[t]) for t in (quarter, half, end)]
        rose = [r for r in kept_running if samples[end][r][key] > samples[three_quarters][r][key]]
        expect(top[2] - top[1] <= top[1] - top[0],
               f"{key}: highest {top[0]} at {quarter:g} s, {top[1]} at {half:g} s, {top[2]} at {end:g} s "
               f"(rose from {three_quarters:g} s in {len(rose)} of the {len(kept_running)} robots not reset "
               f"from {half:g} s)")
    went_down = [(r, k) for r in kept_running for k, v in samples[half][r].items()
                 if k not in NOT_COUNTERS and samples[end][r].get(k, v) < v]
    expect(not went_down, f"no counter went down between {half:g} s and {end:g} s ({len(kept_running)} robots "
           f"not restarted in between): {went_down[:5]}")
    full = sorted({k for r in robots for k, v in samples[end][r].items() if v == 65535})
    expect(True, f"counters saturated at 65535: {full or 'none'}")
    room = [r for r in robots if samples[end][r]["main_stack_used"] >= samples[end][r]["main_stack_room"] > 0]
    expect(not room, f"no main stack reached its room: {room}")
    full = [r for r in robots if samples[end][r]["thread_stack_room"] <= 0]
    expect(not full, f"no thread stack reached its room: {full}")
    # Rates over the robots that ran each interval through, the second
    # interval's expected count scaled to its robots.
    first_robots, second_robots = steady(quarter, half), steady(three_quarters, end)

    def gained(key, since, until, rs):
        return sum(samples[until][r].get(key, 0) - samples[since][r].get(key, 0) for r in rs)

    def injected(kind, since, until, rs):
        return sum(since < t <= until for r in rs for t in received[r].get(kind, []))

    received = faults_received(log)
    for key in sorted(k for k in samples[end][robots[0]] if k not in NOT_COUNTERS):
        first = gained(key, quarter, half, first_robots)
        second = gained(key, three_quarters, end, second_robots)
        allowed = first * len(second_robots) / max(len(first_robots), 1)
        # A counter the injected faults drive may rise with them: its
        # allowance grows with what its robots were sent in each interval.
        why = ""
        if key in DRIVEN_BY:
            before = injected(DRIVEN_BY[key], quarter, half, first_robots)
            after = injected(DRIVEN_BY[key], three_quarters, end, second_robots)
            allowed = max(allowed, first * after / max(before, 1))
            why = f"; the {DRIVEN_BY[key]} faults that drive it: {before} then {after}"
        expect(second <= allowed + 3 * allowed ** 0.5 + 5,
               f"{key}: {first} from {quarter:g} to {half:g} s ({len(first_robots)} robots not reset in it), "
               f"{second} from {three_quarters:g} to {end:g} s ({len(second_robots)}){why}")
    totals = defaultdict(int)
    for r in robots:
        for k, v in samples[end][r].items():
            totals[k] += v
    lines.append("totals at the end: " + " ".join(f"{k}={v}" for k, v in sorted(totals.items())
                                                   if k not in ("main_stack_room", "thread_stack_room")))
    lines.append(f"resets and brown-outs: {sum(len(v) for v in restarts.values())} on {len(restarts)} robots")
    with open(os.path.join(a.out, "summary.txt"), "a" if a.check_only else "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))
    sys.exit(1 if failed else 0)


main()
