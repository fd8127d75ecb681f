#!/usr/bin/env python3
"""The e-puck2 image in the world under QEMU: where a run's time goes, and
what the robot's OS costs it. The fidelity check's world (two e-pucks among
three objects for 10 s, tests/world/epuck_fidelity.py) is run with the host
build, with the QEMU image of this tree and with the image of BEFORE (the
last tree whose link went over USART2, one byte per QEMU main-loop pass):
wall time, the simulator's and QEMU's CPU time, QEMU's voluntary context
switches per exchange (one exchange: a robot's 10 ms step). The image's
'cpu account' console line gives the robot's busy instructions. Rewrites
its section of docs/benchmarks.md.

The image of this tree runs with the port's default tick, as its console
says (tickless idle since the Cortex-M4 port has it).

    python3 bench/qemu_world_bench.py [--build build] [--before 785a17a] [--runs 3]
"""
import argparse
import os
import re
import statistics
import subprocess
import sys
import time

sys.dont_write_bytecode = True  # no bench/__pycache__ in the source tree
import benchmarks_page  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "tests", "world"))
import epuck_fidelity  # noqa: E402  (the fidelity check's world)

WORK = os.path.join(ROOT, "build-bench", "qemu-world")
BEGIN, END = "<!-- qemu_world_bench: begin -->", "<!-- qemu_world_bench: end -->"
ROBOTS, SECONDS, STEP_S = 2, 10, 0.01
EXCHANGES = ROBOTS * round(SECONDS / STEP_S)
NS_PER_INSTRUCTION = 8  # -icount shift=3
F407_HZ = 168e6


def run(cmd, **kw):
    print("+", " ".join(cmd), file=sys.stderr)
    return subprocess.run(cmd, check=True, text=True, capture_output=True, **kw)


def build(build_dir):
    """The simulator and the tool, and each controller's host build and
    QEMU image: the fidelity check's (kernel), the case study's template
    (its host build by `openswarm build`) and its plain loop."""
    run(["cmake", "--build", build_dir, "--target", "openswarm-sim", "openswarm", "epuck_link_app",
         "clustering_plain", "clustering_app", "qemu_firmware", "openswarm-compare-groups"])
    tests = os.path.join(build_dir, "tests")
    return (os.path.join(build_dir, "sim", "openswarm-sim"),
            {"kernel": (os.path.join(tests, "epuck_link_app"), os.path.join(tests, "qemu", "epuck_link_app_qemu.elf")),
             "template": (os.path.join(tests, "clustering_app", "clustering", "build", "epuck_world", "clustering"),
                          os.path.join(tests, "qemu", "clustering_app_qemu.elf")),
             "plain": (os.path.join(tests, "clustering_plain"), os.path.join(tests, "qemu", "clustering_plain_qemu.elf"))})


def build_before(rev):
    """The test image of rev's tree (its tests/qemu project alone)."""
    tree = os.path.join(WORK, "before-src")
    out = os.path.join(WORK, "before-build")
    subprocess.run(["rm", "-rf", tree], check=True)
    os.makedirs(tree)
    archive = subprocess.run(["git", "-C", ROOT, "archive", rev], check=True, capture_output=True).stdout
    subprocess.run(["tar", "-x", "-C", tree], input=archive, check=True)
    run(["cmake", "-S", os.path.join(tree, "tests", "qemu"), "-B", out, "-G", "Ninja", "-DCMAKE_BUILD_TYPE=MinSizeRel",
         "-DCMAKE_TOOLCHAIN_FILE=" + os.path.join(tree, "ports", "cortex_m4", "cmake", "arm-none-eabi.cmake")])
    run(["cmake", "--build", out, "--target", "epuck_link_app_qemu"])
    return os.path.join(out, "epuck_link_app_qemu.elf")


def qemu_script(name, image, serial_link):
    """The controller: QEMU under GNU time (its CPU time and context
    switches), its console in a file. serial_link: the link on USART2
    (QEMU's second serial port on standard input and output), as before."""
    path = os.path.join(WORK, name + ".sh")
    link = "-serial stdio " if serial_link else ""
    with open(path, "w") as f:
        f.write(f"#!/bin/sh\nexec /usr/bin/time -o {WORK}/{name}-$OPENSWARM_ROBOT_ID.time -f '%U %S %w' "
                f"qemu-system-arm -M netduinoplus2 -display none -monitor none "
                f"-serial file:{WORK}/{name}-$OPENSWARM_ROBOT_ID.console {link}"
                f"-semihosting-config enable=on,target=native,arg=app,arg=--id=$OPENSWARM_ROBOT_ID "
                f"-icount shift=3,align=off,sleep=off -kernel {image}\n")
    os.chmod(path, 0o755)
    return path


def tick_of(name, robot=0):
    """The tick a robot's image ran with, from its 'cpu account' line
    (ports/epuck/epuck2/qemu_world/cpu_account.c): tickless idle,
    periodic, or none (the kernel never started)."""
    with open(os.path.join(WORK, f"{name}-{robot}.console")) as f:
        line = [l for l in f if l.startswith("cpu account:")][-1]
    return re.search(r", tick ([a-z ]+)$", line.rstrip("\n")).group(1)


def before_tick(rev):
    """rev's image predates the tick in the 'cpu account' line: its tree
    says whether the port had tickless idle yet."""
    has = subprocess.run(["git", "-C", ROOT, "cat-file", "-e", f"{rev}:ports/cortex_m4/src/tickless_idle.c"],
                         capture_output=True).returncode == 0
    return "its port's default tick" if has else "periodic tick: its port had no tickless idle"


def timed(sim, name, controller, qemu):
    """One run: wall s, CPU s of everything, of the QEMUs, their voluntary
    switches; the record's folder."""
    before = os.times()
    began = time.monotonic()
    failures = []
    out = epuck_fidelity.run(sim, WORK, name, controller, failures, seconds=SECONDS, says_id=False)
    wall = time.monotonic() - began
    if failures:
        raise SystemExit("\n".join(failures))
    after = os.times()
    cpu = after.children_user + after.children_system - before.children_user - before.children_system
    qemu_cpu = switches = 0
    for robot in range(ROBOTS) if qemu else ():
        with open(os.path.join(WORK, f"{name}-{robot}.time")) as f:
            user, system, waits = f.read().split()[-3:]
        qemu_cpu += float(user) + float(system)
        switches += int(waits)
    return {"wall": wall, "cpu": cpu, "qemu_cpu": qemu_cpu, "switches": switches, "out": out}


def cpu_account(name, robot=0):
    """A robot's 'cpu account' line: us by kind."""
    with open(os.path.join(WORK, f"{name}-{robot}.console")) as f:
        line = [l for l in f if l.startswith("cpu account:")][-1]
    return {k.strip(): int(v) for k, v in re.findall(r"([a-z' ()]+?) (\d+) us", line)}


def median_row(label, runs, host_out):
    walls = [r["wall"] for r in runs]
    same = all(epuck_fidelity.read(r["out"], "trajectories.csv") == epuck_fidelity.read(host_out, "trajectories.csv")
               for r in runs)
    qemu_cpu = statistics.median(r["qemu_cpu"] for r in runs)
    cpu = statistics.median(r["cpu"] for r in runs)
    switches = statistics.median(r["switches"] for r in runs) / EXCHANGES
    return (f"| {label} | {statistics.median(walls):.2f} ({min(walls):.2f}-{max(walls):.2f}) | "
            f"{statistics.median(walls) / EXCHANGES * 1e3:.2f} | {cpu - qemu_cpu:.2f} | {qemu_cpu:.2f} | "
            f"{switches:.1f} | {'yes' if same else 'no'} |")


def cost_rows(account):
    """Per second of the robot's own clock (its kernel's ticks)."""
    rows = []
    for label, key in (("the sensors' deliveries (device layer, camera classifier processor)", "sensors"),
                       ("everything else awake: kernel tick, scheduling, event dispatch, the handler, the LED thread",
                        "other busy")):
        per_s = account[key] * 1e3 / NS_PER_INSTRUCTION / SECONDS
        rows.append(f"| {label} | {per_s:,.0f} | {per_s / F407_HZ * 100:.3f}% |")
    return rows


def section(args, rows, account, loads):
    ratio = account["robot time"] / 1e6 / SECONDS  # virtual s per s of the robot's clock
    return "\n".join([
        BEGIN, "## The e-puck2 image in the world (QEMU)\n",
        f"Measured by `python3 bench/qemu_world_bench.py --runs {args.runs} --before {args.before}` on 2 cores, "
        f"load average {loads[0]:.1f} before and {loads[1]:.1f} after (other engineers' builds: the wall times are "
        "those of a busy machine). The fidelity check's world: 2 e-pucks x 10 s, "
        f"{EXCHANGES} exchanges (a robot's 10 ms step: its inputs, its answer). Median of the runs (range); "
        "CPU times are the simulator's own and the QEMUs' summed; switches are QEMU's voluntary context "
        "switches per exchange; 'same' says the world's record is byte for byte the host build's.\n",
        "| controller | wall s | wall ms per exchange | simulator CPU s (with the host build's controllers) | QEMU CPU s | QEMU switches per exchange | same |",
        "|---|---|---|---|---|---|---|", *rows, "",
        f"What the robot's CPU does, from this tree's image's `cpu account` line (robot 0; it ran with "
        f"{tick_of('now')}, the port's default; TIM2 counts QEMU's virtual "
        "time, 8 ns an instruction with `-icount shift=3`; the world link's own work is left out). The controller "
        "is `tests/world/epuck_link_app.c`: the case study's camera handler and a thread blinking the LEDs. "
        "The share is of a 168 MHz STM32F407 at one instruction a cycle (a real one needs more cycles: flash "
        "wait states, exception entry), so it is a lower bound. QEMU's virtual time ran "
        f"{ratio:.2f} s per second of the robot's clock: netduinoplus2's SysTick, set for 168 MHz, ticks every "
        f"{ratio:.2f} ms of virtual time, so under QEMU the robot has {ratio * 1e6 / NS_PER_INSTRUCTION:,.0f} "
        "instructions a millisecond, not 168,000 cycles.\n",
        "| work | instructions per robot-second | share of the CPU |", "|---|---|---|", *cost_rows(account),
        END])


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--build", default=os.path.join(ROOT, "build"), help="a configured build folder of this tree")
    parser.add_argument("--before", default="785a17a", help="the tree to compare with (its link on USART2)")
    parser.add_argument("--runs", type=int, default=3)
    args = parser.parse_args()
    os.makedirs(WORK, exist_ok=True)
    sim, controllers = build(args.build)
    host_app, image = controllers["kernel"]
    before_image = build_before(args.before)
    loads = [os.getloadavg()[0]]
    variants = (("host build (PORT epuck_world)", "host", host_app, False),
                (f"QEMU image, link on USART2 ({args.before}, {before_tick(args.before)})", "before",
                 qemu_script("before", before_image, True), True),
                ("QEMU image, link through semihosting (this tree, {tick})", "now", qemu_script("now", image, False), True))
    runs = {name: [] for _, name, _, _ in variants}
    for _ in range(args.runs):  # interleaved: the machine's load falls on every variant alike
        for _, name, controller, qemu in variants:
            runs[name].append(timed(sim, name, controller, qemu))
    loads.append(os.getloadavg()[0])
    host_out = runs["host"][0]["out"]
    rows = [median_row(label.format(tick=tick_of("now")), runs[name], host_out) for label, name, _, _ in variants]
    text = section(args, rows, cpu_account("now"), loads)
    print(text)
    benchmarks_page.write_section(BEGIN, END, text)


if __name__ == "__main__":
    main()
