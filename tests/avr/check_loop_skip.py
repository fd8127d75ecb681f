#!/usr/bin/env python3
"""Fast-forwarded loops are exact (sim/src/loop_skip.h): a run that skips
the repeats of loops that change nothing and the same run with
--no-loop-skip print the same bytes, end with the same status and write
the same files.

    check_loop_skip.py SIM OUT MIN_PERCENT ARG...

runs SIM ARG... both ways. '{out}' in an argument is a folder of the run's
own (OUT/skip, OUT/no_skip); every file either run writes there is
compared. The run that skips must say it fast-forwarded at least
MIN_PERCENT of the cycles: runs that skipped nothing would prove nothing."""
import filecmp
import os
import re
import shutil
import subprocess
import sys

SUMMARY = re.compile(r"openswarm-sim: ran .* real time(; (\d+)% of the cycles fast-forwarded[^\n]*)?\n")


def run(sim, args, out):
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    argv = [sim] + [a.replace("{out}", out) for a in args]
    done = subprocess.run(argv, capture_output=True, text=True, timeout=1200)
    # The summary's wall time differs from run to run, and the folders' names.
    summary = SUMMARY.search(done.stderr)
    stderr = SUMMARY.sub("", done.stderr).replace(out, "{out}")
    return done.returncode, done.stdout.replace(out, "{out}"), stderr, summary


def files(folder):
    return sorted(os.path.relpath(os.path.join(d, f), folder)
                  for d, _, names in os.walk(folder) for f in names)


def main():
    sim, out, min_percent, args = sys.argv[1], sys.argv[2], float(sys.argv[3]), sys.argv[4:]
    skip_dir, plain_dir = os.path.join(out, "skip"), os.path.join(out, "no_skip")
    skip = run(sim, args, skip_dir)
    plain = run(sim, args + ["--no-loop-skip"], plain_dir)
    failed = []
    for what, a, b in (("exit status", skip[0], plain[0]), ("standard output", skip[1], plain[1]),
                       ("standard error", skip[2], plain[2])):
        if a != b:
            failed.append(f"{what} differs:\n--- skipping\n{a}\n--- --no-loop-skip\n{b}")
    names = files(skip_dir)
    if names != files(plain_dir):
        failed.append(f"the runs wrote different files: {names} and {files(plain_dir)}")
    for name in names:
        if not filecmp.cmp(os.path.join(skip_dir, name), os.path.join(plain_dir, name), shallow=False):
            failed.append(f"{name} differs between {skip_dir} and {plain_dir}")
    percent = float(skip[3].group(2)) if skip[3] and skip[3].group(2) else 0.0
    if percent < min_percent:
        failed.append(f"the run fast-forwarded {percent:.0f}% of the cycles, expected at least "
                      f"{min_percent:.0f}% (its standard error:\n{skip[2]})")
    for f in failed:
        print("FAIL", f)
    print(f"{len(names) + 3} outputs compared, {percent:.0f}% of the cycles fast-forwarded, "
          f"{len(failed)} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
