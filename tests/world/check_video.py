# Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later (see sim/COPYING).
"""world.output_video: video.mp4 of output_driver's run (--video): one
frame per sample (50), the picture's size (800 x 638), as ffprobe reads it.
usage: check_video.py DRIVER OUT_DIR"""
import os
import shutil
import subprocess
import sys

driver, out = sys.argv[1], sys.argv[2]
shutil.rmtree(out, ignore_errors=True)
p = subprocess.run([driver, out, "--video"], capture_output=True, text=True)
if p.returncode != 0:
    sys.exit(f"output_driver --video failed ({p.returncode}):\n{p.stderr}")
if "video.mp4" not in p.stderr:
    sys.exit(f"video.mp4 is not in the list of files written: {p.stderr!r}")
probe = subprocess.run(["ffprobe", "-v", "error", "-count_frames", "-select_streams", "v:0",
                        "-show_entries", "stream=nb_read_frames,width,height,pix_fmt",
                        "-of", "default=noprint_wrappers=1", os.path.join(out, "video.mp4")],
                       capture_output=True, text=True)
fields = dict(line.split("=", 1) for line in probe.stdout.split())
expected = {"width": "800", "height": "638", "pix_fmt": "yuv420p", "nb_read_frames": "50"}
wrong = {k: fields.get(k) for k, v in expected.items() if fields.get(k) != v}
if probe.returncode != 0 or wrong:
    sys.exit(f"ffprobe: {wrong} (expected {expected})\n{probe.stderr}")
print("video.mp4: 50 frames, 800x638, yuv420p")
