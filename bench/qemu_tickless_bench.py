#!/usr/bin/env python3
"""Tickless idle on the e-puck2 under QEMU: the case study's OpenSwarm image
(the object-clustering template's app, tests/qemu's clustering_app_qemu,
tickless idle by the port's default) against the same image built with the
periodic tick (clustering_app_qemu_ticking), in the fidelity check's world
(2 e-pucks x 10 s) and in the case study's (5 e-pucks, 20 objects x 60 s,
seed 1; the plain loop's image too, for the OS's cost). Per robot-second
of the robots' own clocks: QEMU's host CPU time (user + system, GNU time)
and the instructions the robot is awake for (its 'cpu account'). Says
whether each run's world record is byte for byte its host build's.
Rewrites its section of docs/benchmarks.md.

    python3 bench/qemu_tickless_bench.py [--build build] [--runs 3] [--case-seconds 60]
"""
import argparse
import os
import statistics
import sys

sys.dont_write_bytecode = True  # no bench/__pycache__ in the source tree
import benchmarks_page  # noqa: E402
import qemu_case_study as qcs  # noqa: E402  (the case study's world, its trial and record check)
import qemu_world_bench as qwb  # noqa: E402  (the build, the QEMU script, the account)

BEGIN, END = "<!-- qemu_tickless_bench: begin -->", "<!-- qemu_tickless_bench: end -->"
IMAGES = {"ticking": "clustering_app_qemu_ticking.elf", "tickless": "clustering_app_qemu.elf"}


def qemu_cpu(name, robots):
    """The QEMUs' CPU seconds summed (their GNU time files)."""
    total = 0.0
    for robot in range(robots):
        with open(os.path.join(qwb.WORK, f"{name}-{robot}.time")) as f:
            user, system = f.read().split()[-3:-1]
        total += float(user) + float(system)
    return total


def awake_instructions(name, robots, seconds):
    """The robots' mean instructions awake per robot-second."""
    accounts = [qwb.cpu_account(name, robot) for robot in range(robots)]
    return statistics.mean(a["sensors"] + a["other busy"] for a in accounts) * 1e3 / qwb.NS_PER_INSTRUCTION / seconds


def fidelity_world(sim, image, name, host_out):
    """The fidelity check's world (2 e-pucks x 10 s) with image on both."""
    failures = []
    out = qwb.epuck_fidelity.run(sim, qwb.WORK, name, qwb.qemu_script(name, image, False), failures,
                                 seconds=qwb.SECONDS, says_id=False)
    if failures:
        raise SystemExit("\n".join(failures))
    same = qwb.epuck_fidelity.read(out, "trajectories.csv") == qwb.epuck_fidelity.read(host_out, "trajectories.csv")
    return same, qemu_cpu(name, qwb.ROBOTS), awake_instructions(name, qwb.ROBOTS, qwb.SECONDS)


def case_world(sim, image, name, host_out, seconds):
    """The case study's world, seed 1, 5 e-pucks with image."""
    out, _ = qcs.trial(sim, name, 1, seconds, qwb.qemu_script(name, image, False))
    return qcs.same(host_out, out), qemu_cpu(name, qcs.ROBOTS), awake_instructions(name, qcs.ROBOTS, seconds)


def row(label, runs, robot_seconds):
    cpu = [r[1] for r in runs]
    return (f"| {label} | {statistics.median(cpu) / robot_seconds * 1e3:.1f} ({min(cpu) / robot_seconds * 1e3:.1f}-"
            f"{max(cpu) / robot_seconds * 1e3:.1f}) | {statistics.median(r[2] for r in runs):,.0f} | "
            f"{'yes' if all(r[0] for r in runs) else 'NO'} |")


def measure(args, sim, controllers, images):
    """Each variant args.runs times, interleaved (the machine's load falls
    on every variant alike): rows of the two worlds' tables, and the OS's
    cost in the case study's world with each tick."""
    fidelity_host, _ = controllers["template"]
    fidelity_host_out = qwb.epuck_fidelity.run(sim, qwb.WORK, "tickless-host", fidelity_host, [], seconds=qwb.SECONDS,
                                               says_id=False)
    case_hosts = {arm: qcs.trial(sim, f"tickless-case-{arm}-host", 1, args.case_seconds, controllers[arm][0])[0]
                  for arm in ("template", "plain")}
    fidelity, case = {k: [] for k in images}, {k: [] for k in list(images) + ["plain"]}
    for _ in range(args.runs):
        for tick, image in images.items():
            fidelity[tick].append(fidelity_world(sim, image, f"tickless-fidelity-{tick}", fidelity_host_out))
            case[tick].append(case_world(sim, image, f"tickless-case-{tick}", case_hosts["template"], args.case_seconds))
    case["plain"].append(case_world(sim, controllers["plain"][1], "tickless-case-plain", case_hosts["plain"],
                                    args.case_seconds))
    plain = case["plain"][0][2]
    cost = {tick: statistics.median(r[2] for r in case[tick]) - plain for tick in images}
    return fidelity, case, plain, cost


def section(args, fidelity, case, plain, cost, loads):
    fidelity_robot_s, case_robot_s = qwb.ROBOTS * qwb.SECONDS, qcs.ROBOTS * args.case_seconds
    header = ["| image | QEMU host CPU ms per robot-second, median (range) | instructions awake per robot-second | "
              "record the host build's |", "|---|---|---|---|"]
    return "\n".join([
        BEGIN, "## Tickless idle on the e-puck2 (QEMU)\n",
        f"Measured by `python3 bench/qemu_tickless_bench.py --runs {args.runs} --case-seconds {args.case_seconds}` "
        f"on 2 cores, load average {loads[0]:.1f} before and {loads[1]:.1f} after (other engineers' builds). "
        "The case study's OpenSwarm image (the object-clustering template's app) built with the periodic 1 ms "
        "tick (`OS_CFG_TICKLESS 0`) and with the Cortex-M4 port's tickless idle (its default, "
        "`ports/cortex_m4/src/tickless_idle.c`); QEMU's host CPU time is user + system of every QEMU, per second "
        "of the robots' own clocks summed; instructions awake are the image's `cpu account` (sensors and the "
        "rest), 8 ns each with `-icount shift=3`.\n",
        f"The fidelity check's world, 2 e-pucks x {qwb.SECONDS} s, {args.runs} runs:\n", *header,
        *(row(tick, fidelity[tick], fidelity_robot_s) for tick in fidelity), "",
        f"The case study's world (5 e-pucks, 20 objects, seed 1) x {args.case_seconds} s, {args.runs} runs of each "
        "image, one of the plain loop's:\n", *header,
        *(row(tick if tick != "plain" else "plain loop (no OS)", case[tick], case_robot_s) for tick in case), "",
        "The OS's cost in the case study's world (the OpenSwarm image's awake instructions less the plain "
        f"loop's {plain:,.0f}): " + ", ".join(f"{cost[t]:,.0f} per robot-second {t}" for t in cost) +
        f" ({cost['tickless'] / qwb.F407_HZ * 100:.3f}% of a 168 MHz F407 at one instruction a cycle, tickless).",
        END])


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--build", default=os.path.join(qwb.ROOT, "build"), help="a configured build folder of this tree")
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--case-seconds", type=int, default=60)
    args = parser.parse_args()
    os.makedirs(qwb.WORK, exist_ok=True)
    sim, controllers = qwb.build(args.build)
    images = {tick: os.path.join(args.build, "tests", "qemu", elf) for tick, elf in IMAGES.items()}
    loads = [os.getloadavg()[0]]
    fidelity, case, plain, cost = measure(args, sim, controllers, images)
    loads.append(os.getloadavg()[0])
    text = section(args, fidelity, case, plain, cost, loads)
    print(text)
    benchmarks_page.write_section(BEGIN, END, text)


if __name__ == "__main__":
    main()
