# Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later (see sim/COPYING).
"""world.output_errors: what output_open says when it cannot do its job: a
folder that cannot be made (a file in the way) and --video without ffmpeg.
usage: check_errors.py DRIVER OUT_DIR"""
import os
import shutil
import subprocess
import sys

driver, out = sys.argv[1], sys.argv[2]
shutil.rmtree(out, ignore_errors=True)
os.makedirs(out)
failures = []

blocker = os.path.join(out, "a_file")
open(blocker, "w").write("in the way\n")
p = subprocess.run([driver, os.path.join(blocker, "run")], capture_output=True, text=True)
want = f"cannot create the output folder {blocker}: a file of that name is in the way; choose another --out folder"
if p.returncode == 0 or want not in p.stderr:
    failures.append(f"folder under a file: status {p.returncode}, said {p.stderr!r}, expected {want!r}")

env = dict(os.environ, PATH=os.path.join(out, "no-such-bin"))
p = subprocess.run([os.path.abspath(driver), os.path.join(out, "video"), "--video"],
                   capture_output=True, text=True, env=env)
want = "--video needs ffmpeg: apt-get install ffmpeg, or drop --video"
if p.returncode == 0 or want not in p.stderr:
    failures.append(f"--video without ffmpeg: status {p.returncode}, said {p.stderr!r}")

if failures:
    sys.exit("FAILED:\n  " + "\n  ".join(failures))
print("errors: folder in the way and missing ffmpeg reported with the fix")
