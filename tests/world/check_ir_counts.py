#!/usr/bin/env python3
"""ir.csv counts what the IR did where the answer is known (docs/world.md,
"What a run leaves"): robots sending twice a second and printing every
frame they hear (tests/avr/world_distances.c), 10 s each:

- two robots at the range's edge (100 mm), ir.loss_pct 0: the channel
  loses nothing, each hears every frame the other sent, and its firmware
  receives about as many (a frame that met the robot's own transmission
  may be lost), one for each "heard" line it printed;
- the same with ir.loss_pct 100 (the chance is 100% at the edge): the
  channel loses every frame, nobody hears or receives any;
- one robot alone: it sends, and hears, loses and receives nothing.

In every run a robot's heard + lost_channel is what the other sent (a
frame still on the air at the sample counts as sent and not yet as heard),
and its counts never fall. With OPENSWARM, `openswarm metrics` gives the
built-in IR metrics of each run as the means over robots of the last
sample's counts.

check_ir_counts.py SIM PROGRAM OUT [OPENSWARM]   (PROGRAM: the .elf or the native .so)"""
import csv
import json
import os
import subprocess
import sys

from behaviour import Checks, run as run_world

sim, program, out = sys.argv[1:4]
openswarm = sys.argv[4] if len(sys.argv) > 4 else None
checks = Checks()
SECONDS = 10
SENT_LEAST = 2 * SECONDS - 2  # twice a second, the first after the robot booted


def world(robots, loss_pct):
    return {"arena": {"width_mm": 400, "height_mm": 300}, "seed": 3, "duration_s": SECONDS,
            "ir": {"range_mm": 100, "loss_pct": loss_pct},
            "robots": [{"grid": {"x_mm": 110, "y_mm": 150, "columns": robots, "rows": 1, "spacing_mm": 100}}]}


def run(name, robots, loss_pct):
    """The run's folder, its ir.csv rows ({robot: [rows in time order]})
    and the "heard" lines each robot printed."""
    folder = os.path.join(out, name)
    os.makedirs(folder, exist_ok=True)
    path = os.path.join(folder, "world.json")
    with open(path, "w") as f:
        json.dump(world(robots, loss_pct), f)
    console = os.path.join(folder, "console.csv")
    run_world(sim, program, path, folder, ("--console-csv", console))
    rows = {}
    with open(os.path.join(folder, "ir.csv")) as f:
        for row in csv.DictReader(f):
            rows.setdefault(int(row["robot"]), []).append({k: float(v) for k, v in row.items()})
    printed = {}
    with open(console) as f:
        for row in csv.DictReader(f):
            if row["line"].startswith("heard "):
                printed[int(row["robot"])] = printed.get(int(row["robot"]), 0) + 1
    return folder, rows, printed


def never_fall(name, rows):
    keys = ("sent", "received", "heard", "lost_channel")
    fell = [(r, k) for r, seq in rows.items() for a, b in zip(seq, seq[1:]) for k in keys if b[k] < a[k]]
    checks.expect(not fell, f"{name}: no count falls from one sample to the next ({fell[:3]})")


def metrics_of(folder):
    """The built-in IR metrics' last values, by `openswarm metrics`."""
    csv_path = os.path.join(folder, "ir_metrics.csv")
    names = ("ir_sent", "ir_received", "ir_lost", "ir_lost_channel")
    args = [openswarm, "metrics", folder, "--csv", csv_path] + [a for n in names for a in ("--metric", n)]
    done = subprocess.run(args, capture_output=True, text=True, timeout=120)
    if done.returncode != 0:
        sys.exit(f"openswarm metrics failed ({done.returncode}) on {folder}:\n{done.stderr}")
    last = {}
    with open(csv_path) as f:
        for row in csv.DictReader(f):
            if row["robot"] == "":
                last[row["metric"]] = float(row["value"])
    return last


def check_metrics(name, folder, rows):
    """Each metric is the mean over robots of its count at the last sample."""
    if openswarm is None:
        return
    got = metrics_of(folder)
    ends = [seq[-1] for seq in rows.values()]
    mean = lambda f: sum(f(e) for e in ends) / len(ends)
    want = {"ir_sent": mean(lambda e: e["sent"]), "ir_received": mean(lambda e: e["received"]),
            "ir_lost": mean(lambda e: e["heard"] + e["lost_channel"] - e["received"]),
            "ir_lost_channel": mean(lambda e: e["lost_channel"])}
    for metric, value in want.items():
        checks.expect(abs(got.get(metric, float("nan")) - value) < 1e-6,
                      f"{name}: {metric} is {got.get(metric)}, the mean of ir.csv's last counts {value}")


def pair(name, loss_pct):
    folder, rows, printed = run(name, 2, loss_pct)
    checks.expect(sorted(rows) == [0, 1], f"{name}: ir.csv has both robots ({sorted(rows)})")
    never_fall(name, rows)
    for me, other in ((0, 1), (1, 0)):
        mine, theirs = rows[me][-1], rows[other][-1]
        offered = mine["heard"] + mine["lost_channel"]
        checks.expect(mine["sent"] >= SENT_LEAST, f"{name}: robot {me} sent {mine['sent']:.0f} frames (>= {SENT_LEAST})")
        checks.expect(theirs["sent"] - 1 <= offered <= theirs["sent"],
                      f"{name}: robot {me} heard {mine['heard']:.0f} and lost {mine['lost_channel']:.0f} "
                      f"of the {theirs['sent']:.0f} frames robot {other} sent")
        checks.expect(mine["received"] == printed.get(me, 0),
                      f"{name}: robot {me} received {mine['received']:.0f} frames and printed "
                      f"{printed.get(me, 0)} (its firmware's own count)")
        if loss_pct == 0:
            checks.expect(mine["lost_channel"] == 0, f"{name}: robot {me}: the channel lost none ({mine['lost_channel']:.0f})")
            checks.expect(mine["received"] >= 0.8 * mine["heard"],
                          f"{name}: robot {me} received {mine['received']:.0f} of the {mine['heard']:.0f} it heard")
        else:
            checks.expect(mine["heard"] == 0 and mine["received"] == 0,
                          f"{name}: robot {me} heard {mine['heard']:.0f} and received {mine['received']:.0f} (none)")
    check_metrics(name, folder, rows)


pair("loss0", 0)
pair("loss100", 100)
folder, rows, printed = run("alone", 1, 0)
alone = rows.get(0, [{}])[-1]
checks.expect(sorted(rows) == [0], f"alone: ir.csv has the one robot ({sorted(rows)})")
checks.expect(alone.get("sent", 0) >= SENT_LEAST, f"alone: it sent {alone.get('sent')} frames")
checks.expect(all(alone.get(k) == 0 for k in ("received", "heard", "lost_channel")),
              f"alone: it received, heard and lost nothing ({alone})")
never_fall("alone", rows)
check_metrics("alone", folder, rows)
checks.finish()
