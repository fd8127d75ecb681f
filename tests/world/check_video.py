# Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later (see sim/COPYING).
"""world.output_video: video.mp4 at its own frame rate, apart from the
samples. output_driver's run (--video) hands the world every 20 ms for 5 s
and a sample every 0.1 s: the video holds 5 s x 25 frames a second = 125
frames (not one per sample), the picture's size (800 x 638), as ffprobe
reads them; frame 100 shows robot 0 where it was at 4.0 s, (130, 50) mm
(it moves 0.8 mm a frame; a frame drawn from the samples, 0.1 s apart,
could be 2 mm off). With SIM ELF WORLD also: the simulator's --video-fps 5
--video-speed 2 over 4 s makes 4 / 2 x 5 = 10 frames at 5 a second.
usage: check_video.py DRIVER OUT_DIR [SIM ELF WORLD]"""
import os
import shutil
import subprocess
import sys

import png

driver, out = sys.argv[1], sys.argv[2]
failures = []


def probe(path):
    done = subprocess.run(["ffprobe", "-v", "error", "-count_frames", "-select_streams", "v:0",
                           "-show_entries", "stream=nb_read_frames,r_frame_rate,width,height,pix_fmt",
                           "-of", "default=noprint_wrappers=1", path], capture_output=True, text=True)
    return dict(line.split("=", 1) for line in done.stdout.split())


def robot_0_x(k):
    """Where frame k draws robot 0 (red), in world mm: the centroid of its
    red pixels near y = 50 mm (the picture's layout: check_picture.py)."""
    frame = os.path.join(out, f"frame{k}.png")
    subprocess.run(["ffmpeg", "-v", "error", "-y", "-i", os.path.join(out, "video.mp4"),
                    "-vf", f"select=eq(n\\,{k})", "-vframes", "1", frame], check=True)
    image = png.read(frame)
    xs = [x for y in range(470, 522) for x in range(16, 784)
          if (lambda p: p[0] > 150 and p[1] < 100 and p[2] < 100)(image.pixel(x, y))]
    return (sum(xs) / len(xs) + 0.5 - 16) / 1.92 if xs else float("nan")


shutil.rmtree(out, ignore_errors=True)
p = subprocess.run([driver, out, "--video"], capture_output=True, text=True)
if p.returncode != 0:
    sys.exit(f"output_driver --video failed ({p.returncode}):\n{p.stderr}")
if "video.mp4" not in p.stderr:
    sys.exit(f"video.mp4 is not in the list of files written: {p.stderr!r}")
fields = probe(os.path.join(out, "video.mp4"))
expected = {"width": "800", "height": "638", "pix_fmt": "yuv420p", "nb_read_frames": "125", "r_frame_rate": "25/1"}
wrong = {k: fields.get(k) for k, v in expected.items() if fields.get(k) != v}
if wrong:
    sys.exit(f"ffprobe: {wrong} (expected {expected})")
x50, x100 = robot_0_x(50), robot_0_x(100)
# The heading tick (towards +x) hides a little of the disc's red: 0.35 mm.
if not abs(x100 - 130) < 0.6:
    failures.append(f"frame 100 (4.0 s) draws robot 0 at x {x100:.2f} mm, not at 130 (it was there then)")
if not abs(x100 - x50 - 40) < 0.2:
    failures.append(f"robot 0 moved {x100 - x50:.2f} mm between frames 50 and 100 (2 s), not 40")

if len(sys.argv) > 3:
    sim, elf, world = sys.argv[3:6]
    done = subprocess.run([sim, "--world", world, "--out", out + "-sim", "-q", "--time", "4", "--video",
                           "--video-fps", "5", "--video-speed", "2", elf], capture_output=True, text=True)
    fields = probe(os.path.join(out + "-sim", "video.mp4"))
    if done.returncode != 0 or fields.get("nb_read_frames") != "10" or fields.get("r_frame_rate") != "5/1":
        failures.append(f"the simulator's video: {fields} (exit {done.returncode}), expected 10 frames "
                        f"at 5/1\n{done.stderr}")
if failures:
    sys.exit("FAILED:\n  " + "\n  ".join(failures))
print(f"video.mp4: 125 frames at 25 a second, 800x638, yuv420p; robot 0 drawn at {x100:.2f} mm at 4.0 s; "
      "the simulator's rate and speed")
