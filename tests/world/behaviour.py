"""What the behaviour checks (check_orbit.py, check_phototaxis.py,
check_gradient.py) share: run the simulator in a world, read the robots'
paths, count the checks."""
import csv
import subprocess
import sys


def run(sim, elf, world, out, extra=()):
    """Runs ELF in WORLD, writing OUT (with the simulator options extra).
    How long it takes is not checked: a busy machine may take any time, and
    the test's ctest TIMEOUT bounds a run that hangs."""
    done = subprocess.run([sim, "--world", world, "--out", out, "-q", *extra, elf],
                          capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"openswarm-sim failed ({done.returncode}):\n{done.stderr}")


def paths(out):
    """Each robot's samples: (time_s, x_mm, y_mm, heading_deg, (r, g, b))."""
    robots = {}
    with open(f"{out}/trajectories.csv") as f:
        for row in csv.DictReader(f):
            robots.setdefault(int(row["robot"]), []).append(
                (float(row["time_s"]), float(row["x_mm"]), float(row["y_mm"]), float(row["heading_deg"]),
                 (int(row["led_r"]), int(row["led_g"]), int(row["led_b"]))))
    return robots


class Checks:
    def __init__(self):
        self.passed, self.failed = 0, 0

    def expect(self, ok, what):
        print(("ok   " if ok else "FAIL ") + what)
        if ok:
            self.passed += 1
        else:
            self.failed += 1

    def finish(self):
        print(f"{self.passed} passed, {self.failed} failed")
        sys.exit(1 if self.failed else 0)
