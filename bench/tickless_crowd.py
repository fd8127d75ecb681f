#!/usr/bin/env python3
"""Tickless idle in a crowd: the disperse template, built by the tool with
the periodic tick and with `"tickless": true`, run by 100 Kilobots in one
IR range (tests/world/worlds/hundred.json) with seeds 1 to 9. For each run:
how many robots heard a neighbour closer than 60 mm (LED red) in 5 s, the
median time they first did, and the frames the robots received, and lost
(refused by a full queue, bad CRC, broken, collided), from their own
counters. Rewrites its section of docs/benchmarks.md.

    python3 bench/tickless_crowd.py       # builds into build-bench/; about 5 minutes on 2 cores
"""
import concurrent.futures
import csv
import json
import os
import re
import statistics
import sys

sys.dont_write_bytecode = True  # no bench/__pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import benchmarks_page  # noqa: E402
import world_bench  # noqa: E402  (its build of the tool and the simulator, and app())

ROOT = world_bench.ROOT
WORLD = os.path.join(ROOT, "tests", "world", "worlds", "hundred.json")
OUT = os.path.join(world_bench.APPS, "tickless_crowd")
SEEDS = range(1, 10)
COMMAND = "python3 bench/tickless_crowd.py"
BEGIN, END = "<!-- tickless_crowd: begin -->", "<!-- tickless_crowd: end -->"
LOST = ("ir_refused", "ir_bad_crc", "ir_broken", "ir_collisions")


def build():
    world_bench.run(["cmake", "-S", ROOT, "-B", world_bench.HOST, "-G", "Ninja",
                     "-DOPENSWARM_TESTS=OFF", "-DCMAKE_BUILD_TYPE=Release"])
    world_bench.run(["cmake", "--build", world_bench.HOST, "--target", "openswarm-sim", "openswarm"])
    return {"periodic tick": world_bench.app("disperse", "template"),
            "tickless idle": world_bench.app("disperse_tickless", "template", {"tickless": True},
                                              template="disperse")}


def run_seed(elf, tag, seed):
    """One run: its counters and first-red times."""
    where = os.path.join(OUT, f"{tag}-{seed}")
    os.makedirs(where, exist_ok=True)
    with open(WORLD) as f:
        world = json.load(f)
    world["seed"] = seed
    path = os.path.join(where, "world.json")
    with open(path, "w") as f:
        json.dump(world, f)
    done = world_bench.run([world_bench.SIM, "--world", path, "--out", where, "--threads", "1",
                            "--counters", "0", "--no-progress", elf])
    totals = {}
    for line in done.stderr.splitlines() + done.stdout.splitlines():
        if line.startswith("counters "):
            for key, value in re.findall(r"(\w+)=(\d+)(?:\s|$)", line):
                totals[key] = totals.get(key, 0) + int(value)
    first_red = {}
    with open(os.path.join(where, "trajectories.csv")) as f:
        for row in csv.DictReader(f):
            if row["led_r"] == "3" and row["led_g"] == "0":
                first_red.setdefault(row["robot"], float(row["time_s"]))
    print(f"  {tag} seed {seed}: {len(first_red)} red, {totals.get('ir_received', 0)} frames received",
          file=sys.stderr)
    return {"red": len(first_red), "median_s": statistics.median(first_red.values()) if first_red else None,
            "received": totals.get("ir_received", 0), "lost": sum(totals.get(k, 0) for k in LOST)}


def measure(elves):
    jobs = {}
    with concurrent.futures.ThreadPoolExecutor(max_workers=os.cpu_count() or 1) as pool:
        for mode, elf in elves.items():
            for seed in SEEDS:
                jobs[(mode, seed)] = pool.submit(run_seed, elf, mode.split()[0], seed)
    return {key: job.result() for key, job in jobs.items()}


def section(results, modes):
    lines = [BEGIN, "## Tickless idle in a crowd\n",
             "100 Kilobots in one IR range (`tests/world/worlds/hundred.json`, 5 s) run the disperse",
             "template as the tool builds it, with the periodic tick and with `\"tickless\": true`, for",
             "seeds 1 to 9: robots that heard a neighbour closer than 60 mm (LED red), the median",
             "time they first did, and the frames all robots received and lost (refused by a full",
             "queue, bad CRC, broken, collided), from their counters. Produced by",
             f"`{COMMAND}`.\n",
             "| seed | " + " | ".join(f"{m}: red, median s, received, lost" for m in modes) + " |",
             "|---:|" + "---|" * len(modes)]
    for seed in SEEDS:
        cells = []
        for m in modes:
            r = results[(m, seed)]
            median = f"{r['median_s']:.1f}" if r["median_s"] is not None else "-"
            cells.append(f"{r['red']}, {median}, {r['received']}, {r['lost']}")
        lines.append(f"| {seed} | " + " | ".join(cells) + " |")
    means = []
    for m in modes:
        rs = [results[(m, s)] for s in SEEDS]
        medians = [r["median_s"] for r in rs if r["median_s"] is not None]  # a run nobody heard in has none
        means.append(f"{statistics.mean(r['red'] for r in rs):.1f}, "
                     f"{statistics.mean(medians) if medians else float('nan'):.2f}, "
                     f"{statistics.mean(r['received'] for r in rs):.0f}, "
                     f"{statistics.mean(r['lost'] for r in rs):.0f}")
    lines.append("| mean | " + " | ".join(means) + " |")
    lines.append(END)
    return "\n".join(lines)


def main():
    elves = build()
    print(f"running {len(SEEDS) * len(elves)} swarms of 100 for 5 simulated s", file=sys.stderr)
    results = measure(elves)
    text = section(results, list(elves))
    benchmarks_page.write_section(BEGIN, END, text)
    print(text)
    print(f"tickless_crowd: {len(results)} runs, docs/benchmarks.md updated", file=sys.stderr)


if __name__ == "__main__":
    main()
