#!/usr/bin/env python3
"""Compare a trace written by openswarm-sim --trace-csv with an expected one.

usage: expect_trace.py EXPECTED ACTUAL.csv
Each expected line is `time_s,device,a,b,c` (robot 0) or
`time_s,robot,device,a,b,c`; times may differ by 5 ms."""
import csv
import sys

TOLERANCE_S = 0.005


def main(expected_path, actual_path):
    expected = []
    with open(expected_path) as f:
        for n, line in enumerate(f, 1):
            line = line.strip()
            if line and not line.startswith("#"):
                fields = line.split(",")
                if len(fields) == 5:
                    fields.insert(1, "0")
                t, robot, device, a, b, c = fields
                expected.append((n, float(t), int(robot), device, int(a), int(b), int(c)))
    with open(actual_path) as f:
        actual = [(float(r["time_s"]), int(r["robot"]), r["device"], int(r["a"]), int(r["b"]),
                   int(r["c"])) for r in csv.DictReader(f)]
    failures = 0
    # Robots run in lockstep windows: rows of different robots at the same
    # time may come in either order, so each robot's rows are compared alone.
    for robot in sorted({e[2] for e in expected} | {a[1] for a in actual}):
        mine = [e for e in expected if e[2] == robot]
        theirs = [a for a in actual if a[1] == robot]
        for i, (n, t, _, device, a, b, c) in enumerate(mine):
            want = f"robot {robot} {device} {a} {b} {c} at {t:.3f} s"
            if i >= len(theirs):
                print(f"{expected_path}:{n}: expected {want}, the trace ended")
                failures += 1
                continue
            at, _, adev, aa, ab, ac = theirs[i]
            if (adev, aa, ab, ac) != (device, a, b, c) or abs(at - t) > TOLERANCE_S:
                print(f"{expected_path}:{n}: expected {want}, got {adev} {aa} {ab} {ac} at {at:.6f} s")
                failures += 1
        for at, _, adev, aa, ab, ac in theirs[len(mine):]:
            print(f"{actual_path}: unexpected robot {robot} {adev} {aa} {ab} {ac} at {at:.6f} s")
            failures += 1
    print(f"{len(expected) - failures if failures <= len(expected) else 0} passed, {failures} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1], sys.argv[2]))
