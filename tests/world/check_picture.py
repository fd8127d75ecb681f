# Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later (see sim/COPYING).
"""world.output_picture: final.png of output_driver's run. The layout is
picture.c's: the arena's long side (400 mm) takes 768 pixels, 16 pixels of
margin around it and a 30-pixel strip below, so 800 x 638 and a pixel at
(16 + 1.92 x, 592 - 1.92 y) for the world's (x, y).
usage: check_picture.py DRIVER OUT_DIR"""
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import png  # noqa: E402

driver, out = sys.argv[1], sys.argv[2]
shutil.rmtree(out, ignore_errors=True)
p = subprocess.run([driver, out, "--quiet"], capture_output=True, text=True)
if p.returncode != 0 or p.stderr:
    sys.exit(f"output_driver failed ({p.returncode}) or spoke with --quiet:\n{p.stderr}")
image = png.read(os.path.join(out, "final.png"))
failures = []
if (image.width, image.height) != (800, 638):
    sys.exit(f"final.png is {image.width}x{image.height}, expected 800x638")

SCALE, LEFT, BOTTOM = 1.92, 16, 16 + 300 * 1.92


def at(x, y):
    return image.pixel(int(LEFT + x * SCALE), int(BOTTOM - y * SCALE))


def expect(x, y, colour, what, tolerance=2):
    got = at(x, y)
    if any(abs(a - b) > tolerance for a, b in zip(got, colour)):
        failures.append(f"{what} at ({x}, {y}) mm: pixel {got}, expected {colour}")


# The robots at 4.9 s, each in its LED's colour (2-bit channels times 85).
expect(148, 50, (255, 0, 0), "robot 0 (LED 3,0,0)")
expect(140.12, 153.77, (0, 255, 0), "robot 1 (LED 0,3,0)")
expect(320, 120, (85, 170, 255), "robot 2 (LED 1,2,3)")
expect(300, 230, (80, 80, 88), "the obstacle")
expect(109.8, 220, (205, 55, 45), "the object")
expect(180, 40, (248, 247, 242), "the floor", tolerance=4)
expect(-5, 150, (214, 218, 224), "outside the arena")
# The heading: robot 0 looks along +x, so its rim at +x is drawn over
# (dark or white), its rim at -x is its LED's red.
if at(148 + 12, 50) == (255, 0, 0):
    failures.append("robot 0's heading line (towards +x) is not drawn")
# Text in the strip below: some dark pixels at the bottom left (the time).
dark = sum(1 for x in range(16, 90) for y in range(608, 630) if sum(image.pixel(x, y)) < 200)
if dark < 20:
    failures.append(f"no time written at the bottom left ({dark} dark pixels)")

if failures:
    sys.exit("FAILED:\n  " + "\n  ".join(failures))
print("final.png: 800x638, robots in their LED colours, obstacle, object, floor, time")
