# Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later (see sim/COPYING).
"""world.output_viewer: viewer.html of output_driver's run in headless
Chromium. viewer.html?t=2.5 shows 2.5 s paused and writes a report into
the page (#report: ready, time, where each robot is drawn, errors caught);
--dump-dom reads it, --screenshot shows the pixels. Checked: no script
error (caught in the page or "Uncaught" on Chromium's log), the robots where
the run puts them at 2.5 s (one scale, y up, arena fitted), in their LED's
colour on the screen; #t=1 works too.
usage: check_viewer.py DRIVER OUT_DIR"""
import html
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import png  # noqa: E402

driver, out = sys.argv[1], sys.argv[2]
shutil.rmtree(out, ignore_errors=True)
p = subprocess.run([driver, out, "--quiet"], capture_output=True, text=True)
if p.returncode != 0:
    sys.exit(f"output_driver failed ({p.returncode}):\n{p.stderr}")
page = "file://" + os.path.abspath(os.path.join(out, "viewer.html"))
chromium = shutil.which("chromium") or shutil.which("chromium-browser")
if not chromium:
    sys.exit("no chromium on the PATH: apt-get install chromium")
WIDTH, HEIGHT = 1000, 700
failures = []


def browse(url, *action):
    """Runs headless Chromium on url; returns (stdout, stderr). Virtual time
    lets the page settle however loaded the machine is."""
    profile = tempfile.mkdtemp(prefix="viewer-test-", dir=out)
    try:
        r = subprocess.run([chromium, "--headless", "--disable-gpu", "--no-sandbox",
                            "--no-first-run", "--user-data-dir=" + profile,
                            "--force-device-scale-factor=1", "--hide-scrollbars",
                            f"--window-size={WIDTH},{HEIGHT}", "--virtual-time-budget=5000",
                            "--enable-logging=stderr", "--v=0", *action, url],
                           capture_output=True, text=True, timeout=100)
    finally:
        shutil.rmtree(profile, ignore_errors=True)
    for line in r.stderr.splitlines():
        if "Uncaught" in line or ("CONSOLE" in line and "error" in line.lower()):
            failures.append(f"Chromium logged: {line.strip()}")
    return r.stdout, r.stderr


def report(url):
    dom, log = browse(url, "--dump-dom")
    m = re.search(r'<pre id="report">(.*?)</pre>', dom, re.S)
    if not m or not m.group(1).strip():
        sys.exit(f"no report in the page at {url}\n--- DOM (start) ---\n{dom[:2000]}\n--- log ---\n{log[-3000:]}")
    r = json.loads(html.unescape(m.group(1)))
    if r.get("errors"):
        failures.append(f"errors in the page at {url}: {r['errors']}")
    if not r.get("ready"):
        failures.append(f"viewer not ready at {url}")
    return r


r = report(page + "?t=2.5")
if abs(r["time"] - 2.5) > 1e-9:
    failures.append(f"?t=2.5 shows time {r['time']}")
at = r["robots"]
if len(at) != 3:
    sys.exit(f"report has {len(at)} robots, expected 3: {r}")
# Robots at 2.5 s (output_driver.c): 0 at (100, 50), 1 at (200, 210), 2 at (320, 120).
world = [(100, 50), (200, 210), (320, 120)]
scale = (at[2]["x"] - at[0]["x"]) / (world[2][0] - world[0][0])
scale_y = (at[0]["y"] - at[2]["y"]) / (world[2][1] - world[0][1])
if abs(scale - scale_y) > 0.01 * scale:
    failures.append(f"x and y scales differ (or y is not up): {scale} and {scale_y} px/mm")
left, bottom = at[0]["x"] - 100 * scale, at[0]["y"] + 50 * scale
x1, y1 = left + 200 * scale, bottom - 210 * scale
if abs(x1 - at[1]["x"]) > 1 or abs(y1 - at[1]["y"]) > 1:
    failures.append(f"robot 1 drawn at {at[1]}, expected ({x1:.1f}, {y1:.1f})")
# The 400 x 300 arena fills the canvas (the window below the bar) but for a margin.
vw, vh = r["viewport"]
if not (abs(400 * scale - (vw - 32)) < 2 or abs(300 * scale - (vh - 32)) < 2):
    failures.append(f"arena not fitted in {vw}x{vh}: {scale:.3f} px/mm")

# The screenshot (Chromium gives it a taller viewport than --dump-dom's, so
# its robots are found by colour): each LED's colour makes one disc 33 mm
# across, the three where the run has them at 2.5 s under one scale, y up.
shot = os.path.join(out, "viewer-2.5.png")
browse(page + "?t=2.5", "--screenshot=" + shot)
image = png.read(shot)
blobs = []
for i, colour in enumerate([(255, 0, 0), (0, 255, 0), (147, 208, 255)]):
    xs = ys = n = 0
    for y in range(image.height):
        row = image.rows[y]
        for x in range(image.width):
            c = row[x * image.channels:x * image.channels + 3]
            if abs(c[0] - colour[0]) <= 3 and abs(c[1] - colour[1]) <= 3 and abs(c[2] - colour[2]) <= 3:
                xs, ys, n = xs + x, ys + y, n + 1
    if n < 50:
        sys.exit(f"FAILED: robot {i}'s LED colour {colour} is not on the screenshot ({n} pixels)\n" +
                 "\n  ".join(failures))
    blobs.append((xs / n + 0.5, ys / n + 0.5, n))
s_shot = (blobs[2][0] - blobs[0][0]) / (world[2][0] - world[0][0])
s_shot_y = (blobs[0][1] - blobs[2][1]) / (world[2][1] - world[0][1])
x1, y1 = blobs[0][0] + 100 * s_shot, blobs[0][1] - 160 * s_shot
if abs(s_shot - s_shot_y) > 0.02 * s_shot or abs(x1 - blobs[1][0]) > 3 or abs(y1 - blobs[1][1]) > 3:
    failures.append(f"screenshot: robots at {blobs}, scales {s_shot:.3f} / {s_shot_y:.3f}, "
                    f"robot 1 expected near ({x1:.0f}, {y1:.0f})")
for i, (_, _, n) in enumerate(blobs):
    disc = 3.14159 * (16.5 * s_shot) ** 2  # less the outline and the heading line
    if not 0.7 * disc < n <= disc:
        failures.append(f"screenshot: robot {i} covers {n} pixels of its colour, a 33 mm disc {disc:.0f}")
floor = image.pixel(int(blobs[0][0] + 80 * s_shot), int(blobs[0][1] - 40 * s_shot))
if any(abs(a - b) > 4 for a, b in zip(floor, (248, 247, 242))):
    failures.append(f"screenshot: floor at (180, 90) mm is {floor}")

r = report(page + "#t=1")
if abs(r["time"] - 1.0) > 1e-9 or abs(r["robots"][0]["x"] - (left + 70 * scale)) > 1:
    failures.append(f"#t=1: time {r['time']}, robot 0 at {r['robots'][0]} (expected x {left + 70 * scale:.1f})")

if failures:
    sys.exit("FAILED:\n  " + "\n  ".join(failures))
print(f"viewer.html: 2.5 s shown paused, robots placed and coloured right ({scale:.3f} px/mm), no errors")
