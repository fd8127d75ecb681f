#!/usr/bin/env python3
"""The native mode against the exact mode: one behaviour's metric over
several seeds in each, and Welch's t-test on the two sets.

    crosscheck.py SIM BEHAVIOUR EXACT.elf NATIVE.so WORLD OUT SEEDS [SECONDS] [--differ]

runs WORLD (its "seed" replaced by 1..SEEDS, for SECONDS of simulated time
or its duration_s) with the firmware in the exact mode and the same program
built natively, computes the behaviour's metric from each run's
trajectories.csv (or console.csv), and prints both means, their
difference and the test's p-value. The modes agree when p >= 0.01: no evidence at the 1% level that
the metric's mean differs (docs/world.md, "Native mode"). Exits 1 when they
do not agree; with --differ, the other way round: a program whose
behaviour hangs on what the modes do differently (16-bit `int`) must be
caught (native.int16_move_to_light). bench/native_bench.py runs it on every behaviour with more
seeds for the docs; tests/native runs a small version.

Metrics (larger or smaller is not better; they only have to agree):
  disperse    mean nearest-neighbour distance at the end, mm
  orbit       mean distance of the planet from its 60 mm orbit after 20 s, mm
  phototaxis  mean final distance to the lamp over the starting distance
  gradient    time until every robot shows its hop count's colour to the end, s
  synchronisation  mean spread of a flash over the robots in the second half, s
  reception   frames a robot heard, mean over the robots (a program that prints
              "heard" for each: tests/avr/world_distances.c)
"""
import csv
import json
import math
import os
import subprocess
import sys
from collections import deque
from concurrent.futures import ThreadPoolExecutor

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "world"))
from behaviour import paths  # noqa: E402


def disperse(robots, world, out):
    last = [p[-1][1:3] for p in robots.values()]
    return sum(min(math.dist(a, b) for b in last if b is not a) for a in last) / len(last)


def orbit(robots, world, out):
    star, planet = robots[0], robots[1]
    sx, sy = star[-1][1:3]
    late = [math.hypot(x - sx, y - sy) for t, x, y, _, _ in planet if t >= 20.0]
    return sum(abs(d - 60.0) for d in late) / len(late)


def phototaxis(robots, world, out):
    lamp = (world["light"]["sources"][0]["x_mm"], world["light"]["sources"][0]["y_mm"])
    return sum(math.dist(p[-1][1:3], lamp) / math.dist(p[0][1:3], lamp) for p in robots.values()) / len(robots)


COLOURS = {0: (3, 0, 0), 1: (0, 3, 0), 2: (0, 0, 3)}


def gradient(robots, world, out):
    """Hop counts by breadth-first search over the IR range from robot 0
    (the seed); the first sample time from which every robot's LED stays
    its hop count's colour (white for 3 or more)."""
    reach = world.get("ir", {}).get("range_mm", 100)
    where = {i: p[0][1:3] for i, p in robots.items()}
    hops, queue = {0: 0}, deque([0])
    while queue:
        i = queue.popleft()
        for j in where:
            if j not in hops and math.dist(where[i], where[j]) <= reach:
                hops[j] = hops[i] + 1
                queue.append(j)
    settled = 0.0
    for i, p in robots.items():
        want = COLOURS.get(hops.get(i, 99), (3, 3, 3))
        for t, _, _, _, led in reversed(p):
            if led != want:
                settled = max(settled, t)
                break
    return settled


def synchronisation(robots, world, out):
    """How far apart the robots flash once they have had time to agree:
    over robot 0's flashes in the second half of the run, the mean of the
    largest distance from one to any robot's nearest flash, s."""
    white = (3, 3, 3)
    onsets = {i: [p[k][0] for k in range(1, len(p)) if p[k][4] == white and p[k - 1][4] != white]
              for i, p in robots.items()}
    half = max(p[-1][0] for p in robots.values()) / 2
    gaps = [max(min(abs(t - u) for u in onsets[i]) for i in onsets) for t in onsets[0] if t >= half]
    return sum(gaps) / len(gaps)


def reception(robots, world, out):
    """A crowd's reception: the frames each robot heard, on average."""
    with open(os.path.join(out, "console.csv")) as f:
        heard = sum(1 for row in csv.DictReader(f) if row["line"].startswith("heard "))
    return heard / len(robots)


def run(sim, firmware, world, seed, out, seconds):
    os.makedirs(out, exist_ok=True)
    spec = dict(world, seed=seed)
    path = os.path.join(out, "world.json")
    with open(path, "w") as f:
        json.dump(spec, f)
    extra = ["--time", str(seconds)] if seconds else []
    console = ["--console-csv", os.path.join(out, "console.csv")]
    limit = float(os.environ.get("OPENSWARM_CROSSCHECK_TIMEOUT_S", "3600"))
    try:
        done = subprocess.run([sim, "--world", path, "--out", out, "-q", "--threads", "1", *console, *extra, firmware],
                              capture_output=True, text=True, timeout=limit)
    except subprocess.TimeoutExpired:
        sys.exit(f"openswarm-sim ran past {limit:g} s on seed {seed} ({path}): a loaded machine can take that "
                 "long; OPENSWARM_CROSSCHECK_TIMEOUT_S=SECONDS gives it longer")
    if done.returncode != 0:
        sys.exit(f"openswarm-sim failed ({done.returncode}) on seed {seed}:\n{done.stderr}")
    return paths(out)


def student_t_cdf_tail(t, df):
    """P(|T| >= |t|) for Student's t with df degrees of freedom: the
    regularized incomplete beta I_x(df/2, 1/2), x = df / (df + t^2), by its
    continued fraction (Lentz's method)."""
    x = df / (df + t * t)
    a, b = df / 2.0, 0.5
    front = math.exp(math.lgamma(a + b) - math.lgamma(a) - math.lgamma(b) + a * math.log(x) + b * math.log1p(-x)) / a
    f, c, d = 1.0, 1.0, 0.0
    for i in range(400):
        m = i // 2
        if i == 0:
            num = 1.0
        elif i % 2 == 0:
            num = (m * (b - m) * x) / ((a + 2 * m - 1) * (a + 2 * m))
        else:
            num = -((a + m) * (a + b + m) * x) / ((a + 2 * m) * (a + 2 * m + 1))
        d = 1.0 + num * d
        d = 1.0 / (d if abs(d) > 1e-300 else 1e-300)
        c = 1.0 + num / (c if abs(c) > 1e-300 else 1e-300)
        f *= c * d
        if abs(1.0 - c * d) < 1e-12:
            break
    return min(1.0, front * (f - 1.0))


def welch(xs, ys):
    """Welch's t statistic and its two-sided p-value."""
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    vx = sum((x - mx) ** 2 for x in xs) / (len(xs) - 1)
    vy = sum((y - my) ** 2 for y in ys) / (len(ys) - 1)
    se2 = vx / len(xs) + vy / len(ys)
    if se2 == 0:
        return 0.0, 1.0 if mx == my else 0.0
    t = (mx - my) / math.sqrt(se2)
    df = se2 ** 2 / ((vx / len(xs)) ** 2 / (len(xs) - 1) + (vy / len(ys)) ** 2 / (len(ys) - 1))
    return t, student_t_cdf_tail(t, df)


def crosscheck(sim, behaviour, exact, native, world_path, out, seeds, seconds=None, jobs=1):
    """Both modes' metrics over seeds 1..seeds, jobs runs at a time (each
    run is its own process and seed: the results do not depend on jobs);
    (exact, native, t, p)."""
    with open(world_path) as f:
        world = json.load(f)
    metric = globals()[behaviour]
    results = {}
    with ThreadPoolExecutor(max_workers=jobs) as pool:
        for mode, firmware in (("exact", exact), ("native", native)):
            def one(s, firmware=firmware, mode=mode):
                d = os.path.join(out, f"{mode}{s}")
                return metric(run(sim, firmware, world, s, d, seconds), world, d)
            results[mode] = list(pool.map(one, range(1, seeds + 1)))
    t, p = welch(results["exact"], results["native"])
    return results["exact"], results["native"], t, p


def main():
    args = [a for a in sys.argv[1:] if a != "--differ"]
    differ = len(args) < len(sys.argv) - 1
    if "--help" in args or "-h" in args:
        print(__doc__)
        return
    if len(args) < 7:
        print(__doc__.split("\n\n")[1].strip(), file=sys.stderr)
        sys.exit(f"crosscheck.py: {len(args)} of its 7 arguments given; give all seven, as above "
                 "(bench/native_bench.py runs it with the built programs' paths; --help says more)")
    sim, behaviour, exact, native, world, out, seeds = args[:7]
    seconds = float(args[7]) if len(args) > 7 else None
    xs, ys, t, p = crosscheck(sim, behaviour, exact, native, world, out, int(seeds), seconds)
    mean = lambda v: sum(v) / len(v)  # noqa: E731
    print(f"{behaviour}: exact {mean(xs):.2f} ({', '.join(f'{x:.2f}' for x in xs)}), "
          f"native {mean(ys):.2f} ({', '.join(f'{y:.2f}' for y in ys)}); Welch t {t:.2f}, p {p:.4f}")
    agree = p >= 0.01
    if differ:
        ok = not agree
        print(("ok   " if ok else "FAIL ") + f"the cross-check tells the modes apart on {behaviour} (p {p:.4f} < 0.01)")
    else:
        ok = agree
        print(("ok   " if ok else "FAIL ") + f"the modes agree on {behaviour} (p {p:.3f} >= 0.01)")
    print(f"{int(ok)} passed, {int(not ok)} failed")
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
