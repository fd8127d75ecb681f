#!/usr/bin/env python3
"""The case study's two arms with real instruction timing: the OpenSwarm
arm, the object-clustering template's own app (templates/object-clustering/
main.c, built by `openswarm build --port epuck_world`, and its e-puck2
image, tests/qemu's clustering_app_qemu), and the plain loop
(templates/object-clustering/plain) run in the case study's setup
(docs/case-study.md: 4 x 3 m, 5 e-pucks and 20 objects on random marks of
the 15 x 11 grid) as their host builds and as e-puck2 images under QEMU
(-icount: the kernel runs instruction by instruction), for each seed.
Says whether the world's records are the same byte for byte, the wall
time of each, the robots' CPU from the images' 'cpu account' lines, and
each run's largest cluster at its end (`openswarm metrics`). Rewrites its
section of docs/case-study.md.

Each seed's results are kept in build-bench/qemu-world/case-study-<duration>s.jsonl
as it ends, with the tick each image says it ran with: run again (with as
many or more --trials) and the seeds done are not run again, so the trials
can run in pieces; the page refuses seeds whose images' ticks differ.
Each seed also keeps the commit its world's sources were last changed in
(sim/, ports/, kernel/, the template): a run that would add seeds to a
record made from other sources stops and says so, since the same seeds
then give other trials (--same-world: checked that they do not). Delete
the file to start over.

    python3 bench/qemu_case_study.py [--build build] [--trials 3] [--duration 600] [--jobs 1] [--same-world]
"""
import argparse
import concurrent.futures
import csv
import json
import os
import random
import statistics
import subprocess
import sys
import threading
import time

sys.dont_write_bytecode = True  # no bench/__pycache__ in the source tree
import benchmarks_page  # noqa: E402
import qemu_world_bench as qwb  # noqa: E402  (its build, QEMU script and account)

ROOT = qwb.ROOT
PAGE = os.path.join(ROOT, "docs", "case-study.md")
BEGIN, END = "<!-- qemu_case_study: begin -->", "<!-- qemu_case_study: end -->"
ROBOTS, OBJECTS = 5, 20
COLUMNS, ROWS, SPACING = 15, 11, 250
ARENA = (4000, 3000)
ARMS = (("template", "OpenSwarm"), ("plain", "plain loop"))  # controllers' keys in qemu_world_bench.build


def world(seed, duration, controller):
    """The case study's world for seed: robots and objects on distinct
    marks, robots' headings at random (drawn here, not by the tool's
    experiment runner: the same setup, other draws)."""
    draw = random.Random(seed)
    x0 = (ARENA[0] - (COLUMNS - 1) * SPACING) / 2
    y0 = (ARENA[1] - (ROWS - 1) * SPACING) / 2
    marks = [(x0 + c * SPACING, y0 + r * SPACING) for r in range(ROWS) for c in range(COLUMNS)]
    taken = draw.sample(marks, ROBOTS + OBJECTS)
    poses = [{"x_mm": x, "y_mm": y, "heading_deg": draw.randrange(360)} for x, y in taken[:ROBOTS]]
    objects = [{"x_mm": x, "y_mm": y, "radius_mm": 50, "mass_g": 50, "friction": 0.5} for x, y in taken[ROBOTS:]]
    return {"robot": "epuck", "arena": {"width_mm": ARENA[0], "height_mm": ARENA[1]}, "seed": seed,
            "duration_s": duration, "sample_period_s": 5, "objects": objects,
            "robots": [{"poses": poses, "firmware": controller}]}


def trial(sim, name, seed, duration, controller):
    """One run: its outputs' folder and wall time."""
    path = os.path.join(qwb.WORK, name + ".json")
    with open(path, "w") as f:
        json.dump(world(seed, duration, controller), f)
    out = os.path.join(qwb.WORK, name)
    began = time.monotonic()
    qwb.run([sim, "-q", "--world", path, "--out", out])
    return out, time.monotonic() - began


def same(a, b):
    return all(qwb.epuck_fidelity.read(a, f) == qwb.epuck_fidelity.read(b, f)
               for f in ("trajectories.csv", "objects.csv"))


def busy_per_robot_second(name, duration):
    """The robots' mean instructions per robot-second awake (sensors and
    the rest), from their accounts."""
    accounts = [qwb.cpu_account(name, robot) for robot in range(ROBOTS)]
    busy_us = statistics.mean(a["sensors"] + a["other busy"] for a in accounts)
    return busy_us * 1e3 / qwb.NS_PER_INSTRUCTION / duration


def largest_cluster(openswarm, out, world_file, duration):
    """The share of objects in the largest cluster at the run's end, as
    `openswarm metrics` measures it (docs/experiments.md, "Metrics")."""
    values = os.path.join(out, "largest_cluster.csv")
    qwb.run([openswarm, "metrics", out, "--world", world_file, "-m", "largest_cluster", "--csv", values])
    with open(values) as f:
        at_end = [r for r in csv.DictReader(f) if float(r["time_s"]) == duration]
    return float(at_end[0]["value"])


# What decides a trial: the world, the ports, the kernel and the template.
WORLD_SOURCES = ("sim", "ports", "kernel", "templates/object-clustering")


def world_sources():
    """The last commit that changed WORLD_SOURCES (with "+changes" if the
    tree holds uncommitted ones there), or "unknown" outside a git tree."""
    def git(*args):
        return subprocess.run(["git", "-C", ROOT, *args], text=True, capture_output=True)
    last = git("log", "-1", "--format=%h", "--", *WORLD_SOURCES)
    if last.returncode != 0 or not last.stdout.strip():
        return "unknown"
    dirty = git("status", "--porcelain", "--untracked-files=no", "--", *WORLD_SOURCES).stdout.strip()
    return last.stdout.strip() + ("+changes" if dirty else "")


def seed_runs(sim, openswarm, controllers, seed, duration):
    """Both arms of one seed, each as its host build and its QEMU image."""
    runs = {}
    for arm, label in ARMS:
        host_app, image = controllers[arm]
        name = f"case-{arm}-qemu-{seed}"
        host_out, host_wall = trial(sim, f"case-{arm}-host-{seed}", seed, duration, host_app)
        qemu_out, qemu_wall = trial(sim, name, seed, duration, qwb.qemu_script(name, image, False))
        run = {"seed": seed, "same": same(host_out, qemu_out), "busy": busy_per_robot_second(name, duration),
               "tick": qwb.tick_of(name),
               "host_wall": host_wall, "qemu_wall": qemu_wall,
               "host_cluster": largest_cluster(openswarm, host_out, host_out + ".json", duration),
               "qemu_cluster": largest_cluster(openswarm, qemu_out, qemu_out + ".json", duration)}
        print(f"seed {seed} {label}: {run}", file=sys.stderr, flush=True)
        runs[label] = run
    runs["load"] = os.getloadavg()[0]  # at the seed's end: the machine the walls were measured on
    runs["sources"] = world_sources()
    return runs


class Record:
    """The seeds done, kept a line each as they end (several seeds run
    side by side), so that a later run resumes."""

    def __init__(self, duration):
        self.path = os.path.join(qwb.WORK, f"case-study-{duration}s.jsonl")
        self.lock = threading.Lock()
        self.done = {}
        if os.path.exists(self.path):
            with open(self.path) as f:
                for line in f:
                    kept = json.loads(line)
                    self.done[kept["seed"]] = kept["runs"]

    def keep(self, seed, runs):
        with self.lock, open(self.path, "a") as f:
            f.write(json.dumps({"seed": seed, "runs": runs}) + "\n")
        self.done[seed] = runs

    def ticks(self, seeds):
        """Each arm's tick over seeds; one each, or the record mixes images."""
        ticks = {label: sorted({self.done[seed][label]["tick"] for seed in seeds}) for _, label in ARMS}
        if any(len(t) > 1 for t in ticks.values()):
            raise SystemExit(f"{self.path}: its seeds ran with different ticks ({ticks}): the images were rebuilt "
                             "between pieces of the run; delete the file and run again")
        return {label: t[0] for label, t in ticks.items()}


def mean_sd(values):
    return f"{statistics.mean(values) * 100:.1f}% +- {statistics.stdev(values) * 100 if len(values) > 1 else 0:.1f}"


def compare(build_dir, a, b):
    """The two-point sweep's own comparison of two groups
    (cli/src/sweep/group_comparison.cpp): t, degrees, p, d, detectable;
    or the tool's reason why there is no test (too few values, no spread)."""
    tool = os.path.join(build_dir, "cli", "openswarm-compare-groups")
    done = subprocess.run([tool, ",".join(map(repr, a)), ",".join(map(repr, b))], text=True, capture_output=True)
    if done.returncode == 1:
        return done.stderr.strip()
    if done.returncode != 0:
        raise SystemExit(done.stderr)
    return json.loads(done.stdout)


def summary(results, trials, duration, build_dir):
    """Per arm: the largest cluster at the end, host build and QEMU image,
    mean +- standard deviation over the trials; the instructions awake;
    the arms compared by Welch's t test."""
    lines = [f"| arm | n | largest cluster at {duration} s, host build | under QEMU | records the same | "
             "instructions awake per robot-second (QEMU), mean |", "|---|---:|---|---|---|---|"]
    for label, runs in results.items():
        lines.append(f"| {label} | {trials} | {mean_sd([r['host_cluster'] for r in runs])} | "
                     f"{mean_sd([r['qemu_cluster'] for r in runs])} | {sum(r['same'] for r in runs)} of {trials} | "
                     f"{statistics.mean(r['busy'] for r in runs):,.0f} |")
    cost = statistics.mean(r["busy"] for r in results["OpenSwarm"]) - \
        statistics.mean(r["busy"] for r in results["plain loop"])
    lines.append(f"\nThe OS's cost, the difference of the arms' awake instructions: {cost:,.0f} per robot-second "
                 f"({cost / qwb.F407_HZ * 100:.3f}% of a 168 MHz F407 at one instruction a cycle).")
    c = compare(build_dir, *([r["qemu_cluster"] * 100 for r in results[label]] for _, label in ARMS))
    if isinstance(c, str):
        return lines + [f"\nNo Welch's t test of the arms: {c}."]
    lines.append(f"\nThe arms' largest clusters at {duration} s under QEMU, OpenSwarm against the plain loop, by the "
                 "experiment's own Welch's t test (two-sided; `cli/src/sweep/group_comparison.cpp`, here through "
                 f"`openswarm-compare-groups`): t = {c['t']:.2f} (df {c['degrees']:.1f}), p = {c['p']:.3f}; "
                 f"Cohen's d = {c['d']:.2f}. With these spreads and n = {trials} an arm the test finds a difference "
                 f"of {c['detectable']:.1f} points 80% of the time at alpha 0.05; about "
                 f"{trials * (c['detectable'] / 10) ** 2:.0f} trials an arm would find 10 points.")
    return lines


def run_seeds(args, record, sim, controllers):
    """The seeds 1..args.trials not yet done, args.jobs side by side."""
    openswarm = os.path.join(args.build, "cli", "openswarm")

    def one(seed):
        record.keep(seed, seed_runs(sim, openswarm, controllers, seed, args.duration))

    to_run = [seed for seed in range(1, args.trials + 1) if seed not in record.done]
    here = world_sources()
    kept = sorted({runs.get("sources", "not recorded") for runs in record.done.values()} - {here})
    if to_run and kept and not args.same_world:
        raise SystemExit(f"{record.path}: its {len(record.done)} seeds ran with the world's sources at "
                         f"{', '.join(kept)}, this tree's are at {here} ({', '.join(WORLD_SOURCES)}): new seeds "
                         "would be trials of another world. Delete the file to run every seed afresh, give "
                         f"--trials {len(record.done)} to write the page from the seeds kept, or --same-world "
                         "if you have checked that the change leaves these trials as they were")
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        list(pool.map(one, to_run))  # re-raises a trial's failure


def arm_cells(run):
    """One arm's cells of a seed's row."""
    return (f"{run['host_cluster'] * 100:.0f}% / {run['qemu_cluster'] * 100:.0f}% | {'yes' if run['same'] else 'NO'} | "
            f"{run['host_wall']:.1f} / {run['qemu_wall']:.1f} | {run['busy']:,.0f}")


def section(args, record):
    seeds = range(1, args.trials + 1)
    results = {label: [record.done[seed][label] for seed in seeds] for _, label in ARMS}
    loads = [record.done[seed]["load"] for seed in seeds]
    ticks = record.ticks(seeds)
    rows = [f"| {seed} | " + " | ".join(arm_cells(record.done[seed][label]) for _, label in ARMS) + " |" for seed in seeds]
    return "\n".join([
        BEGIN,
        f"Measured by `python3 bench/qemu_case_study.py --trials {args.trials} --duration {args.duration} "
        f"--jobs {args.jobs}` on 2 cores shared with other builds, load average {min(loads):.1f}-{max(loads):.1f} "
        f"at the seeds' ends: n = {args.trials} trials of {args.duration} s per arm, seeds 1-{args.trials}, "
        f"5 e-pucks each. The images' tick, as they report it: OpenSwarm {ticks['OpenSwarm']}, plain loop "
        f"{ticks['plain loop']}.\n",
        *summary(results, args.trials, args.duration, args.build), "",
        "Per seed, each arm's largest cluster at the end in its host build and under QEMU, whether the two "
        "records are the same byte for byte, each run's wall time and the robots' instructions awake per "
        "robot-second under QEMU:\n",
        "| seed | OpenSwarm: cluster, host / QEMU | same | wall s, host / QEMU | awake | "
        "plain loop: cluster, host / QEMU | same | wall s, host / QEMU | awake |",
        "|---|---|---|---|---|---|---|---|---|", *rows, END])


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    parser.add_argument("--trials", type=int, default=3)
    parser.add_argument("--duration", type=int, default=600)
    parser.add_argument("--jobs", type=int, default=1, help="seeds run side by side (their wall times then share the CPU)")
    parser.add_argument("--same-world", action="store_true",
                        help="add seeds to a record made from other sources (checked to leave the trials as they were)")
    args = parser.parse_args()
    os.makedirs(qwb.WORK, exist_ok=True)
    sim, controllers = qwb.build(args.build)
    record = Record(args.duration)
    print(f"seeds done before: {sorted(record.done)}", file=sys.stderr, flush=True)
    run_seeds(args, record, sim, controllers)
    text = section(args, record)
    print(text)
    benchmarks_page.write_section(BEGIN, END, text, PAGE)


if __name__ == "__main__":
    main()
