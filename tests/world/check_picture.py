# Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later (see sim/COPYING).
"""world.output_picture: final.png of output_driver's run, then of the same
run with --ids. The layout is
picture.c's: the arena's long side (400 mm) takes 768 pixels, 16 pixels of
margin around it and a 30-pixel strip below, so 800 x 638 and a pixel at
(16 + 1.92 x, 592 - 1.92 y) for the world's (x, y).
usage: check_picture.py DRIVER OUT_DIR"""
import math
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


def at(x, y, img=None):
    return (img or image).pixel(int(LEFT + x * SCALE), int(BOTTOM - y * SCALE))


def expect(x, y, colour, what, tolerance=2):
    got = at(x, y)
    if any(abs(a - b) > tolerance for a, b in zip(got, colour)):
        failures.append(f"{what} at ({x}, {y}) mm: pixel {got}, expected {colour}")


# The robots at 4.9 s, each in its LED's colour (2-bit channels as 0, 147,
# 208, 255: the square root of level / 3, as bright as the eye sees it).
expect(148, 50, (255, 0, 0), "robot 0 (LED 3,0,0)")
expect(140.12, 153.77, (0, 255, 0), "robot 1 (LED 0,3,0)")
expect(320, 120, (147, 208, 255), "robot 2 (LED 1,2,3)")
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

# The legend beside the time: a swatch of each LED colour shown at the end.
strip = [image.pixel(x, y) for x in range(100, 520) for y in range(600, 636)]
for colour in ((255, 0, 0), (0, 255, 0), (147, 208, 255)):
    if colour not in strip:
        failures.append(f"no swatch of the LED colour {colour} in the legend below the arena")
# Where robot 0 started, (50, 50): a dashed ring its size (16.5 mm), dark.
ring = sum(1 for a in range(0, 360, 3)
           if sum(at(50 + 16.5 * math.cos(math.radians(a)), 50 + 16.5 * math.sin(math.radians(a)))) < 200)
if ring < 20:
    failures.append(f"robot 0's start at (50, 50) is not marked ({ring} of 120 points on its ring dark)")


def dark_beside(img, x, y):
    """Dark pixels above right of robot (x, y), outside its disc (32 pixels across)."""
    px, py = int(LEFT + x * SCALE), int(BOTTOM - y * SCALE)
    return sum(1 for dx in range(16, 40) for dy in range(-40, -16)
               if dx * dx + dy * dy > 35 * 35 and sum(img.pixel(px + dx, py + dy)) < 200)


if dark_beside(image, 148, 50) > 0:
    failures.append("a number beside robot 0 without --ids")
p = subprocess.run([driver, out + "-ids", "--quiet", "--ids"], capture_output=True, text=True)
numbered = png.read(os.path.join(out + "-ids", "final.png"))
if p.returncode != 0 or dark_beside(numbered, 148, 50) < 5:
    failures.append(f"--ids: no number written beside robot 0 (exit {p.returncode}) {p.stderr}")

# --dim: robot 0 shows the classic labs' dim white, RGB(1,1,1), robot 2 is
# off. The dim white is drawn lit: a light grey, far brighter than the
# unlit robot's dark body (it was 85 against 150: darker than off).
p = subprocess.run([driver, out + "-dim", "--quiet", "--dim"], capture_output=True, text=True)
dimmed = png.read(os.path.join(out + "-dim", "final.png"))
lit, off = at(148, 50, dimmed), at(320, 120, dimmed)
if p.returncode != 0 or lit != (147, 147, 147):
    failures.append(f"--dim: robot 0's dim white (LED 1,1,1) drawn {lit}, expected (147, 147, 147)")
if off != (70, 70, 76) or sum(lit) - sum(off) < 3 * 60:
    failures.append(f"--dim: the dim white {lit} is not clearly brighter than the unlit robot {off}")

if failures:
    sys.exit("FAILED:\n  " + "\n  ".join(failures))
print("final.png: 800x638, robots in their LED colours, obstacle, object, floor, time, "
      "the LEDs' legend, the starts; --ids numbers the robots; the dim white is drawn lit, "
      "distinct from an unlit robot")
