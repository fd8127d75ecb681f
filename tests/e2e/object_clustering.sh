#!/usr/bin/env bash
# End to end: the object-clustering template (the paper's case study) is
# scaffolded for the world (its first port), builds both controllers - the
# OpenSwarm one and the plain loop - and runs a short experiment (2 trials
# x 2 simulated minutes per controller): results.csv is well formed, the
# plot is written as PNG and SVG, each trial leaves its world and pictures,
# and the same experiment again gives the same results.csv, byte for byte.
# It also builds for the e-puck2; bad experiment files are refused.
#   object_clustering.sh OPENSWARM WORKDIR
set -euo pipefail
openswarm=$1 work=$2
rm -rf "$work" && mkdir -p "$work" && cd "$work"
"$openswarm" new clusters --template object-clustering > new.log
grep -q "for epuck_world" new.log
cd clusters
"$openswarm" build > build.log
test -x build/epuck_world/clusters && test -x build/epuck_world/clusters-plain
"$openswarm" experiment experiments/paper.json --trials 2 --duration 120 > experiment.log
cat experiment.log
out=experiments/paper-results
python3 - "$out/results.csv" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert list(rows[0].keys()) == ["trial", "controller", "seed", "time_s", "largest_cluster", "compactness"], rows[0]
keys = {(r["controller"], r["trial"]) for r in rows}
assert keys == {(c, t) for c in ("OpenSwarm", "plain loop") for t in ("1", "2")}, keys
for c, t in keys:
    times = [float(r["time_s"]) for r in rows if (r["controller"], r["trial"]) == (c, t)]
    assert times[0] == 0 and abs(times[-1] - 120) < 1e-6 and len(times) == 25, (c, t, times[:3], len(times))
for r in rows:
    assert 0.05 - 1e-9 <= float(r["largest_cluster"]) <= 1 and float(r["compactness"]) > 0, r
print("results.csv: %d rows, well formed" % len(rows))
PY
head -c 8 "$out/results.png" | od -An -c | grep -q "P   N   G"
grep -q "<svg" "$out/results.svg"
for d in trial-01-openswarm trial-02-openswarm trial-01-plain-loop trial-02-plain-loop; do
  test -s "$out/$d/world.json" && test -s "$out/$d/final.png" && test -s "$out/$d/viewer.html"
done
grep -Eq "^4 of 4 trials ran in " experiment.log
"$openswarm" experiment experiments/paper.json --trials 2 --duration 120 --out again > again.log
cmp "$out/results.csv" again/results.csv
# Bad experiment files: exit 2, the file, the key and the fix.
printf '{"arena": {"width_mm": 4000, "height_mm": 3000}}' > bad.json
status=0; "$openswarm" experiment bad.json 2> bad.log || status=$?
test "$status" -eq 2 && grep -q 'bad.json: "marks": missing; add "marks" there' bad.log
sed 's|build/epuck_world/clusters-plain|build/epuck_world/no-such|' experiments/paper.json > experiments/missing.json
status=0; "$openswarm" experiment experiments/missing.json 2> missing.log || status=$?
test "$status" -eq 2 && grep -q 'controller "plain loop": .*no-such does not exist: build it first' missing.log
"$openswarm" build --port epuck2 > epuck2.log
test -s build/epuck2/clusters.elf
echo "1 passed, 0 failed"
