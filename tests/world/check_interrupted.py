#!/usr/bin/env python3
"""Every output is whole or absent (issue 30): a world run stopped by
SIGINT or SIGTERM writes what it simulated so far, and a run killed with
SIGKILL leaves the previous outputs as they were.

  SIGINT / SIGTERM, once the run is under way (trajectories.csv.part has
  rows): exit 130 / 143; one line names the signal, the simulated time and
  the files; trajectories.csv and objects.csv end on a whole record no
  later than that time; final.png is a PNG, viewer.html ends with </html>;
  no .part file is left. Kilobots in the exact mode, in the native mode
  (when its shared object is given), with --video (when ffmpeg is there),
  and e-pucks (their stand-in controller) each.
  SIGKILL mid-run: the previous run's files are byte for byte as they were.

check_interrupted.py SIM KILOBOT.elf NATIVE.so|- DOUBLE.py WORKDIR
"""
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import time

SIM, ELF, NATIVE, DOUBLE, WORK = sys.argv[1:6]
COLUMNS = {"trajectories.csv": 8, "objects.csv": 4}
failures = []


def check(name, ok, detail):
    if not ok:
        failures.append(f"{name}: {detail}")


def world(name, kind):
    """A world that runs much longer than the test waits: 20 minutes."""
    spec = {"arena": {"width_mm": 1200, "height_mm": 400}, "seed": 3, "duration_s": 1200,
            "objects": [{"x_mm": 600, "y_mm": 300, "radius_mm": 20}]}
    if kind == "epuck":
        spec.update(robot="epuck", robots=[{"poses": [{"x_mm": 200, "y_mm": 200, "heading_deg": 0}],
                                            "firmware": DOUBLE}])
    else:
        spec["robots"] = [{"grid": {"x_mm": 100, "y_mm": 100, "columns": 5, "rows": 1, "spacing_mm": 200}}]
        if kind == "native":
            spec["fidelity"] = "native"
    path = os.path.join(WORK, name + ".json")
    with open(path, "w") as f:
        json.dump(spec, f)
    return path


def start(name, kind, extra=()):
    out = os.path.join(WORK, name)
    firmware = {"exact": [ELF], "native": [NATIVE], "epuck": []}[kind]
    command = [SIM, "--no-progress", "--world", world(name, kind), "--out", out, *extra, *firmware]
    # SIGINT as from a terminal, even if this test started with it ignored
    # (which the simulator respects: interrupt.c).
    return out, subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                                 env={**os.environ, "EPUCK_WHEELS": "300,200"},
                                 preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))


def wait_under_way(name, out, proc):
    """Until trajectories.csv.part holds some samples (not a fixed sleep)."""
    part = os.path.join(out, "trajectories.csv.part")
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline and proc.poll() is None:
        if os.path.exists(part) and os.path.getsize(part) > 4096:
            return True
        time.sleep(0.05)
    check(name, False, f"the run never got under way (exit {proc.poll()}): {proc.stderr.read() if proc.poll() is not None else ''}")
    return False


def last_record(path):
    with open(path, "rb") as f:
        text = f.read().decode()
    check(path, text.endswith("\n"), "does not end with a newline: a record was cut")
    return text.rstrip("\n").split("\n")[-1].split(",")


def check_whole(name, out, at_s, video):
    for table, columns in COLUMNS.items():
        path = os.path.join(out, table)
        if not os.path.exists(path):
            check(name, False, f"no {table}")
            continue
        last = last_record(path)
        check(name, len(last) == columns, f"{table}'s last line has {len(last)} columns, not {columns}: {last}")
        check(name, float(last[0]) <= at_s + 1e-9, f"{table} goes on to {last[0]} s, past the {at_s} s it names")
    png = os.path.join(out, "final.png")
    check(name, os.path.exists(png) and open(png, "rb").read(8) == b"\x89PNG\r\n\x1a\n", "final.png is not a PNG")
    viewer = os.path.join(out, "viewer.html")
    check(name, os.path.exists(viewer) and open(viewer).read().endswith("</html>\n"),
          "viewer.html does not end with </html>")
    if video:
        mp4 = os.path.join(out, "video.mp4")
        check(name, os.path.exists(mp4) and open(mp4, "rb").read(12)[4:8] == b"ftyp", "video.mp4 is not an MP4")
    left = [f for f in os.listdir(out) if f.endswith(".part")]
    check(name, not left, f".part files left: {left}")


def interrupt(name, kind, sig, extra=()):
    out, proc = start(name, kind, extra)
    if not wait_under_way(name, out, proc):
        proc.kill()
        proc.wait()
        return
    proc.send_signal(sig)
    try:
        _, stderr = proc.communicate(timeout=120)
    except subprocess.TimeoutExpired:
        proc.kill()
        check(name, False, "did not stop within 120 s of the signal")
        return
    check(name, proc.returncode == 128 + sig, f"exit {proc.returncode}, expected {128 + sig}:\n{stderr}")
    said = re.search(r"interrupted by (SIG[A-Z]+) at ([0-9.]+) s of simulated time: wrote the run up "
                     r"to then to (.*); exit status ([0-9]+)", stderr)
    if not said:
        check(name, False, f"no line saying when it was interrupted and what it wrote:\n{stderr}")
        return
    check(name, said.group(1) == signal.Signals(sig).name, f"names {said.group(1)}")
    check(name, "trajectories.csv" in said.group(3) and "viewer.html" in said.group(3), f"names {said.group(3)}")
    check_whole(name, out, float(said.group(2)), "--video" in extra)


def killed_keeps_previous():
    """A whole run, then one killed with SIGKILL in the same folder."""
    name = "killed"
    out = os.path.join(WORK, name)
    first = subprocess.run([SIM, "-q", "--world", world(name, "exact"), "--time", "2", "--out", out, ELF],
                           capture_output=True, text=True, timeout=120)
    check(name, first.returncode == 0, f"the first run failed: {first.stderr}")
    before = {f: open(os.path.join(out, f), "rb").read() for f in os.listdir(out)}
    _, proc = start(name, "exact")
    if wait_under_way(name, out, proc):
        proc.kill()
    proc.wait()
    for f, data in before.items():
        path = os.path.join(out, f)
        check(name, os.path.exists(path) and open(path, "rb").read() == data,
              f"{f} is not the previous run's any more (SIGKILL left it half-written or gone)")


shutil.rmtree(WORK, ignore_errors=True)
os.makedirs(WORK)
interrupt("sigint", "exact", signal.SIGINT)
interrupt("sigterm", "exact", signal.SIGTERM)
interrupt("epuck", "epuck", signal.SIGINT)
if NATIVE != "-":
    interrupt("native", "native", signal.SIGTERM)
if shutil.which("ffmpeg"):
    interrupt("video", "exact", signal.SIGINT, ["--video"])
killed_keeps_previous()
for f in failures:
    print("FAIL", f)
print("ok" if not failures else f"{len(failures)} failure(s)")
sys.exit(1 if failures else 0)
