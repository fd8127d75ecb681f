#!/usr/bin/env bash
# End to end: the case study as a sweep file (the object-clustering
# template's experiments/case-study.json: the two controllers as the
# "program" place, robots and objects on marks, the built-in
# largest_cluster and compactness) gives the same numbers as the
# clustering experiment file (experiments/paper.json): 2 trials x 60 s x
# both controllers, every sample of every trial equal to the printed
# precision; with --native, the same values again. The template's world
# runs on its own, too.
#   case_study_sweep.sh OPENSWARM WORKDIR
set -euo pipefail
openswarm=$1 work=$2
rm -rf "$work" && mkdir -p "$work" && cd "$work"
source "$(dirname "$0")/check.sh"

"$openswarm" new clusters --template object-clustering >/dev/null
cd clusters
"$openswarm" build >build.log 2>&1 || fail "the build" build.log
"$openswarm" experiment experiments/paper.json --trials 2 --duration 60 --out old >old.log 2>&1 ||
    fail "the clustering experiment" old.log
"$openswarm" experiment experiments/case-study.json --trials 2 --duration 60 --out new >new.log 2>&1 ||
    fail "the sweep" new.log
grep -q "^Sweeping 2 points x 2 trials = 4 trials of arena.json" new.log || fail "the sweep's first line" new.log
grep -q "^4 of 4 trials done (0 by an earlier run), 0 failed" new.log || fail "the sweep's trials" new.log
python3 - old/results.csv new/results.csv <<'PY' || fail "the same numbers both ways" old/results.csv new/results.csv
import csv, sys
program = {"OpenSwarm": "clusters", "plain loop": "clusters-plain"}
old, new = {}, {}
for r in csv.DictReader(open(sys.argv[1])):
    for metric in ("largest_cluster", "compactness"):
        old[(program[r["controller"]], r["trial"], r["seed"], r["time_s"], metric)] = r[metric]
for r in csv.DictReader(open(sys.argv[2])):
    new[(r["program"], r["trial"], r["seed"], "%.3f" % float(r["time_s"]), r["metric"])] = r["value"]
assert old.keys() == new.keys(), sorted(set(old) ^ set(new))[:5]
assert len(old) == 2 * 2 * 13 * 2, len(old)
for k in old:
    a, b = float(old[k]), float(new[k])
    # old: %.4f; new: %.6g - equal within half a unit of the coarser last digit
    assert abs(a - b) <= 5e-5 + 5e-6 * abs(b) + 1e-12, (k, old[k], new[k])
print("%d values, equal both ways" % len(old))
PY
# --native: every point in the native mode (the controllers built for the
# host, in the simulator's process), the same values - the native e-puck
# mode is the pipe mode's byte for byte (native.epuck_same_as_pipe).
"$openswarm" experiment experiments/case-study.json --trials 2 --duration 60 --out native --native >native.log 2>&1 ||
    fail "the sweep with --native" native.log
grep -q "^Built .*build/epuck_world-native/clusters.so (native)$" native.log || fail "the native build" native.log
grep -q '"fidelity": "native"' native/point-02/trial-02/world.json || fail "a native trial's world" native/point-02/trial-02/world.json
test "$(wc -l <native/results.csv)" -eq "$((1 + 2 * 2 * 13 * 2))" && cmp -s new/results.csv native/results.csv ||
    fail "--native gives the exact sweep's values" new/results.csv native/results.csv
# The world the sweep starts from is a world of its own (trial 1's).
"$openswarm" run --world worlds/arena.json >world.log 2>&1 || fail "the template's world" world.log
echo "the case study as a sweep gives the clustering experiment's numbers"
