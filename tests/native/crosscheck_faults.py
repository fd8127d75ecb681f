#!/usr/bin/env python3
"""--faults in the native mode against the exact mode.

    crosscheck_faults.py SIM EXACT.elf NATIVE.so OUT SEEDS

runs tests/avr/fault_ir_payload.c (robot 0 sends 150 frames, robots 1-3
count what they receive; 4 robots 50 mm apart) in both modes and checks:
  IR faults: the frames each receiver heard under --faults flip=1 and
  under cut=40, seeds 1..SEEDS, agree between the modes by Welch's t-test
  (p >= 0.01, as tests/native/crosscheck.py), and the faults lost frames in
  both (a native mode that ignored them would hear all 150);
  the plan: under reset=1800,brownout=900 the two logs name the same
  resets and brown-outs of the same robots in the same order, each native
  one within a native window (1 ms) after the exact one (the exact mode's
  windows are 8 us);
  drift and blank: drift:0=5,drift=1,blank:2 logs the same lines in both
  modes, in the same order (every robot's drift, robot 0's 5% fast, and
  robot 2's blank calibration), and in both robot 0 ends its sending (and
  stops) 1.05 times sooner in world time than undrifted (+- 0.002).
"""
import os
import re
import subprocess
import sys

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from crosscheck import welch  # noqa: E402

FRAMES = 150
STATS = re.compile(r"\[robot ([1-9]\d*)\] uid \d+ sent \d+ ((?:\w+ \d+ ?)+)")
STOPPED = re.compile(r"\[robot 0\] stopped at ([0-9.]+) s")
WINDOW_S = 0.001


def run(sim, robot, out, name, faults, seconds, expect_stop=True):
    """One run of four robots; (stdout, stderr, the fault log's lines)."""
    os.makedirs(out, exist_ok=True)
    log = os.path.join(out, name + ".log")
    args = [sim, "--robots", "4", "--distance", "50", "--time", str(seconds), "--threads", "1",
            "--faults", faults, "--fault-log", log, robot]
    if expect_stop:
        args.insert(1, "--expect-stop")
    done = subprocess.run(args, capture_output=True, text=True, timeout=300)
    if done.returncode != 0:
        sys.exit(f"openswarm-sim failed ({done.returncode}) on {robot} --faults {faults}:\n{done.stderr}")
    with open(log) as f:
        return done.stdout, done.stderr, [dict(kv.split("=", 1) for kv in line.split()[1:]) for line in f]


def receivers(sim, robot, out, name, faults):
    """Each receiver's counters as it printed them: received, bad_crc, ..."""
    stdout, _, _ = run(sim, robot, out, name, faults, 6)
    return [{k: int(v) for k, v in re.findall(r"(\w+) (\d+)", counters)} for _, counters in STATS.findall(stdout)]


def heard(sim, robot, out, name, faults):
    """Frames each receiver heard."""
    return [r["received"] for r in receivers(sim, robot, out, name, faults)]


class Checks:
    def __init__(self):
        self.passed = self.failed = 0

    def expect(self, ok, what):
        print(("ok   " if ok else "FAIL ") + what)
        self.passed += bool(ok)
        self.failed += not ok


def ir_faults(checks, sim, elf, so, out, seeds):
    for spec in ("flip=1", "cut=40"):
        modes = {}
        for mode, robot in (("exact", elf), ("native", so)):
            modes[mode] = [n for s in seeds for n in heard(sim, robot, out, f"{mode}-{spec}-{s}", f"{spec},seed={s}")]
        xs, ys = modes["exact"], modes["native"]
        t, p = welch(xs, ys)
        mean = lambda v: sum(v) / len(v)  # noqa: E731
        print(f"{spec}: frames heard of {FRAMES}, exact {mean(xs):.1f} {xs}, native {mean(ys):.1f} {ys}; "
              f"Welch t {t:.2f}, p {p:.4f}")
        checks.expect(len(xs) == len(ys) == 3 * len(seeds), f"{spec}: every receiver reported in both modes")
        checks.expect(p >= 0.01, f"{spec}: the modes agree on the frames heard (p {p:.3f} >= 0.01)")
        checks.expect(max(mean(xs), mean(ys)) < 0.9 * FRAMES, f"{spec}: the faults lost frames in both modes")


def plan(checks, sim, elf, so, out):
    spec = "reset=1800,brownout=900,brownout-ms=20,seed=3"
    logs = {mode: [f for f in run(sim, robot, out, f"{mode}-plan", spec, 3.5, expect_stop=False)[2]
                   if f["kind"] in ("reset", "brownout")]
            for mode, robot in (("exact", elf), ("native", so))}
    exact, native = logs["exact"], logs["native"]
    print("plan, exact:  " + ", ".join(f"{f['kind']} {f['robot']} {f['t']}" for f in exact))
    print("plan, native: " + ", ".join(f"{f['kind']} {f['robot']} {f['t']}" for f in native))
    checks.expect(len(exact) >= 4, f"the plan has {len(exact)} resets and brown-outs")
    same = [(f["kind"], f["robot"]) for f in exact] == [(f["kind"], f["robot"]) for f in native]
    checks.expect(same, "the same resets and brown-outs of the same robots, in the same order")
    late = [float(n["t"]) - float(e["t"]) for e, n in zip(exact, native)]
    checks.expect(same and all(-1e-5 <= d <= WINDOW_S + 1e-5 for d in late),
                  f"each native one within a window after the exact one (at most {max(late, default=0):.6f} s)")


def drift(checks, sim, elf, so, out):
    spec = "drift:0=5,drift=1,blank:2"
    results = {}
    for mode, robot in (("exact", elf), ("native", so)):
        _, stderr, log = run(sim, robot, out, f"{mode}-drift", spec, 6)
        undrifted = float(STOPPED.search(run(sim, robot, out, f"{mode}-none", "seed=1", 6)[1]).group(1))
        results[mode] = (float(STOPPED.search(stderr).group(1)), undrifted, log)
    for mode, (stopped, undrifted, _) in results.items():
        ratio = undrifted / stopped
        checks.expect(abs(ratio - 1.05) < 0.002, f"{mode}: robot 0 5% fast stops at {stopped:.4f} s, "
                      f"{ratio:.4f} times sooner than at {undrifted:.4f} s undrifted")
    kinds = [(f["kind"], f["robot"]) for f in results["native"][2]]
    checks.expect(results["exact"][2] == results["native"][2] and len(kinds) == 5,
                  f"the same drifts and blank calibration logged in both modes, in the same order: {kinds}")


def main():
    sim, elf, so, out, seeds = sys.argv[1:6]
    checks = Checks()
    ir_faults(checks, sim, elf, so, out, range(1, int(seeds) + 1))
    plan(checks, sim, elf, so, out)
    drift(checks, sim, elf, so, out)
    print(f"{checks.passed} passed, {checks.failed} failed")
    sys.exit(1 if checks.failed else 0)


if __name__ == "__main__":
    main()
