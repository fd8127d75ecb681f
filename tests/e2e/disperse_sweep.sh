#!/usr/bin/env bash
# End to end: the disperse template's sweep (experiments/crowd.json), one
# trial of 10 s per point: 3, 6 and 9 Kilobots packed in the middle of the
# arena, IR loss 0 and 20%. In every point the robots spread: the mean
# nearest-neighbour distance at the end is above its value at the start,
# which is the same at both losses (the same seed places them alike); the
# summary has each point's two metrics, and the plots are drawn.
#   disperse_sweep.sh OPENSWARM WORKDIR
set -uo pipefail
openswarm=$1 work=$2
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
source "$(dirname "$0")/check.sh"

"$openswarm" new d --template disperse >/dev/null || fail "the app"
"$openswarm" experiment d/experiments/crowd.json --trials 1 --duration 10 --out r >r.log 2>&1 || fail "the sweep" r.log
grep -q "^Sweeping 6 points x 1 trial = 6 trials of packed.json" r.log || fail "the first line" r.log
grep -q "^6 of 6 trials done (0 by an earlier run), 0 failed" r.log || fail "the trials" r.log
test "$(grep -c '^[1-6],[0-9]*,[369],nearest_neighbour_mm,1,0,' r/summary.csv)" -eq 6 &&
    test "$(grep -c '^[1-6],[0-9]*,[369],largest_group,1,0,' r/summary.csv)" -eq 6 || fail "the summary" r/summary.csv
python3 - r/results.csv <<'PY' || fail "the robots spread in every point" r/results.csv
import csv, sys
start, end = {}, {}
for r in csv.DictReader(open(sys.argv[1])):
    if r["metric"] != "nearest_neighbour_mm":
        continue
    key = (r["ir.loss_pct"], r["robots[0].count"])
    if float(r["time_s"]) == 0:
        start[key] = float(r["value"])
    if float(r["time_s"]) == 10:
        end[key] = float(r["value"])
assert len(start) == len(end) == 6, (start, end)
for key in start:
    assert end[key] > start[key] + 10, (key, start[key], end[key])
    assert start[key] == start[("0", key[1])], key
print({k: (start[k], end[k]) for k in start})
PY
for metric in nearest_neighbour_mm largest_group; do
    head -c 4 "r/plots/$metric.png" | grep -q PNG || fail "the $metric plot" r.log
done
echo "the disperse sweep ran, the robots spread, and it plotted"
