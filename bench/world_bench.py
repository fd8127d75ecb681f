#!/usr/bin/env python3
"""World simulator speed: simulated robot-seconds per wall-clock second for
swarms of 1, 10, 50 and 100 Kilobots in a world, with firmware that keeps
the CPU busy, firmware as the disperse template is written (it sleeps
between its moves) and firmware that mostly sleeps, on one thread and on
every core. Rewrites its section of docs/benchmarks.md.

    python3 bench/world_bench.py          # builds into build-bench/
"""
import glob
import json
import math
import os
import shutil
import subprocess
import sys
import time

sys.dont_write_bytecode = True  # no bench/__pycache__ in the source tree
import benchmarks_page  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BUILD = os.path.join(ROOT, "build-bench")
HOST = os.path.join(BUILD, "host")
SIM = os.path.join(HOST, "sim", "openswarm-sim")
TOOL = os.path.join(HOST, "cli", "openswarm")
APPS = os.path.join(BUILD, "world")
COMMAND = "python3 bench/world_bench.py"
BEGIN, END = "<!-- world_bench: begin -->", "<!-- world_bench: end -->"
SWARMS = (1, 10, 50, 100)
SIMULATED_S = {1: 60, 10: 30, 50: 10, 100: 5}


def run(cmd, **kw):
    print("+", " ".join(cmd), file=sys.stderr)
    return subprocess.run(cmd, check=True, text=True, capture_output=True, **kw)


def app(name, source, kernel=None, template=None):
    """Copy an app (the template NAME, or TEMPLATE, or bench/world/NAME),
    with kernel settings added to its openswarm.json, and build it with the
    tool."""
    where = os.path.join(APPS, name)
    shutil.rmtree(where, ignore_errors=True)
    if source == "template":
        os.makedirs(APPS, exist_ok=True)
        run([TOOL, "new", name, "-C", APPS, "--template", template or name, "--force"])
    else:
        shutil.copytree(source, where)
    if kernel:
        config = os.path.join(where, "openswarm.json")
        with open(config) as f:
            settings = json.load(f)
        settings["kernel"] = kernel
        with open(config, "w") as f:
            json.dump(settings, f, indent=2)
    run([TOOL, "build", "-C", where])
    elves = glob.glob(os.path.join(where, "build", "kilobot", "*.elf"))
    return elves[0]


def build():
    run(["cmake", "-S", ROOT, "-B", HOST, "-G", "Ninja", "-DOPENSWARM_TESTS=OFF",
         "-DCMAKE_BUILD_TYPE=Release"])
    run(["cmake", "--build", HOST, "--target", "openswarm-sim", "openswarm"])
    busy = os.path.join(ROOT, "bench", "world", "disperse_busy")
    return {
        "busy": app("disperse_busy", busy),
        "idle_loop": app("disperse_idle_loop", busy, {"kilolib_idle_loop": True}),
        "disperse": app("disperse", "template"),
        "asleep": app("blinky", "template"),
    }


def world(n):
    """n robots at random in a square that gives each about 80 x 80 mm, in
    an arena twice as wide: the density of the disperse template's world."""
    side = max(120, round(80 * math.sqrt(n)))
    arena = 2 * side + 200
    path = os.path.join(APPS, f"world_{n}.json")
    with open(path, "w") as f:
        json.dump({"arena": {"width_mm": arena, "height_mm": arena}, "seed": 1,
                   "robots": [{"count": n, "region": {"x_mm": (arena - side) / 2,
                                                      "y_mm": (arena - side) / 2,
                                                      "width_mm": side, "height_mm": side}}]}, f)
    return path


def speed(elf, n, threads):
    """Real-time factor of one run: simulated seconds per wall second."""
    seconds = SIMULATED_S[n]
    start = time.monotonic()
    run([SIM, "--world", world(n), "--time", str(seconds), "--threads", str(threads), "-q",
         "--no-progress", elf])
    return seconds / (time.monotonic() - start)


def factor(x):
    """A real-time factor: two decimals below 1x, one above."""
    return f"{x:.2f}x" if x < 1 else f"{x:.1f}x"


def table(elves, cores):
    lines = ["| firmware | robots | 1 thread | %d threads | robot-seconds per second |" % cores,
             "|---|---:|---:|---:|---:|"]
    names = {
        "busy": "busy (`bench/world/disperse_busy`: the disperse behaviour with a classic loop() that never sleeps)",
        "idle_loop": "the same busy program with `\"kilolib_idle_loop\": true`",
        "disperse": "disperse template (sleeps between moves)",
        "asleep": "blinky template (asleep between 1 ms ticks)",
    }
    results = {}
    for kind, elf in elves.items():
        for n in SWARMS:
            one = speed(elf, n, 1)
            many = speed(elf, n, cores) if n >= 2 * cores else one
            best = max(one, many)
            results[(kind, n)] = best
            lines.append(f"| {names[kind]} | {n} | {factor(one)} | "
                         f"{factor(many) if n >= 2 * cores else '-'} | {n * best:.0f} |")
    return lines, results


def verdict(results):
    busy50 = results[("busy", 50)]
    idle50 = results[("idle_loop", 50)]
    disperse50 = results[("disperse", 50)]
    asleep100 = results[("asleep", 100)]
    return [
        f"- 50 Kilobots running disperse at real time or faster: the template "
        f"{factor(disperse50)} ({'met' if disperse50 >= 1 else 'not met'}); the busy classic loop "
        f"{factor(busy50)} ({'met' if busy50 >= 1 else 'not met'}), {factor(idle50)} with "
        f"kilolib_idle_loop ({'met' if idle50 >= 1 else 'not met'}).",
        f"- 100 robots with sleeping firmware at 5x real time or faster: {factor(asleep100)} "
        f"({'met' if asleep100 >= 5 else 'not met'}).",
    ]


def write(lines):
    benchmarks_page.write_section(BEGIN, END, "\n".join([BEGIN] + lines + [END]))


def main():
    elves = build()
    cores = os.cpu_count() or 1
    rows, results = table(elves, cores)
    lines = ["## World simulator speed", "",
             f"`{COMMAND}` on {cores} cores: robots in a world (`--world`), placed at random",
             "about 80 mm apart, physics every 10 ms, no outputs written. Real-time factor =",
             "simulated seconds per wall-clock second; robot-seconds per second = robots x the",
             "better of the two.", ""] + rows + [""] + verdict(results) + [""]
    write(lines)
    print("\n".join(lines))


if __name__ == "__main__":
    main()
