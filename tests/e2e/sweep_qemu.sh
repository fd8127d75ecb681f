#!/usr/bin/env bash
# End to end: a sweep of the object-clustering template over "fidelity":
# ["exact", "qemu"] and "program" (its OpenSwarm controller and its plain
# loop), 2 e-pucks among 3 objects for 4 s: the app's e-puck2 images are
# built once (build/epuck_world-qemu/), the qemu points' e-pucks run in
# QEMU, and each qemu trial's record (trajectories.csv, objects.csv) and
# metrics are the host build's byte for byte, as world.epuck2_qemu_template
# and world.epuck2_qemu_plain establish for these controllers. A QEMU that
# fails or hangs fails its trials with the reason, the others kept, and
# the same command then runs only those; qemu-system-arm missing, and a Kilobot
# app's sweep asking for qemu, are refused with the fix. `openswarm run
# --world` with a trial's world runs the image too.
#   sweep_qemu.sh OPENSWARM WORKDIR
set -uo pipefail
openswarm=$1 work=$2
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
source "$(dirname "$0")/check.sh"

# A Kilobot app's sweep asking for qemu: refused before anything is built.
"$openswarm" new blinks --template blinky >/dev/null && mkdir -p blinks/worlds || fail "the Kilobot app"
cat >blinks/worlds/qemu.json <<'JSON'
{"arena": {"width_mm": 300, "height_mm": 300}, "duration_s": 1, "robots": [{"count": 2}]}
JSON
cat >blinks/qemu-sweep.json <<'JSON'
{"world": "worlds/qemu.json", "grid": {"fidelity": ["exact", "qemu"]}}
JSON
expect 2 'blinks/qemu-sweep.json: "fidelity": "qemu" \(fidelity="qemu"\) runs e-pucks. e-puck2 images under QEMU, .* drop "qemu" from the file.s "fidelity" values' \
    "$openswarm" experiment blinks/qemu-sweep.json
test ! -e blinks/build || fail "the refused sweep built the app"

"$openswarm" new clusters --template object-clustering >/dev/null && cd clusters || fail "the e-puck app"
cat >worlds/two.json <<'JSON'
{"robot": "epuck", "arena": {"width_mm": 1000, "height_mm": 800}, "seed": 3, "sample_period_s": 0.1,
 "objects": [{"x_mm": 600, "y_mm": 400, "radius_mm": 50, "mass_g": 50, "friction": 0.5},
             {"x_mm": 300, "y_mm": 600, "radius_mm": 50, "mass_g": 50, "friction": 0.5},
             {"x_mm": 700, "y_mm": 200, "radius_mm": 50, "mass_g": 50, "friction": 0.5}],
 "robots": [{"poses": [{"x_mm": 200, "y_mm": 400, "heading_deg": 0}, {"x_mm": 800, "y_mm": 600, "heading_deg": 180}]}]}
JSON
cat >experiments/qemu.json <<'JSON'
{"world": "../worlds/two.json", "duration_s": 4, "trials": 1,
 "grid": {"fidelity": ["exact", "qemu"], "program": ["clusters", "clusters-plain"]},
 "metrics": ["largest_cluster", "compactness"]}
JSON

# qemu-system-arm missing (a PATH without it): said with the fix.
mkdir -p nobin
expect 1 'qemu-system-arm was not found: sudo apt-get install qemu-system-arm' \
    env PATH="$PWD/nobin" "$openswarm" experiment experiments/qemu.json --out results

# A QEMU that fails (a stand-in that exits 1): those trials fail with
# the reason, the host builds' are done and kept.
mkdir -p badqemu && printf '#!/bin/sh\necho "qemu-system-arm: stand-in failure" >&2\nexit 1\n' >badqemu/qemu-system-arm
chmod +x badqemu/qemu-system-arm
status=0
PATH="$PWD/badqemu:$PATH" "$openswarm" experiment experiments/qemu.json --out results >bad.log 2>&1 || status=$?
test "$status" -eq 1 || fail "a failing QEMU: exit $status, not 1" bad.log
grep -q "^Built .*build/epuck_world-qemu/clusters.elf (e-puck2 image for QEMU)$" bad.log || fail "the QEMU image's build" bad.log
grep -q "^2 of 4 trials done (0 by an earlier run), 2 failed" bad.log || fail "the failing QEMU's trials" bad.log
# Progress: a line as each trial ends, with the failures so far.
grep -Eq "^\[[1-4]/4\] point [34], trial 1: FAILED; [12] failed, [0-9]+ s so far" bad.log &&
    grep -Eq "^\[[1-4]/4\] point [12], trial 1: largest_cluster [0-9.]+; [0-2] failed, [0-9]+ s so far" bad.log ||
    fail "the progress lines" bad.log
grep -q "^3,1,1,qemu,clusters,failed,\"an e-puck's controller failed (the simulator says which and how):$" results/trials.csv && grep -q "^1,1,1,exact,clusters,done," results/trials.csv &&
    grep -q "^openswarm-sim: robot 0's controller .*/clusters.elf exited with status 1" results/trials.csv ||
    fail "trials.csv: the QEMU trials failed with the reason, the others done" results/trials.csv

# A QEMU that hangs (a stand-in that never answers): killed after the
# link's wait, its trials failed with the reason; the others done before.
mkdir -p hungqemu && printf '#!/bin/sh\nexec sleep 600\n' >hungqemu/qemu-system-arm && chmod +x hungqemu/qemu-system-arm
status=0
PATH="$PWD/hungqemu:$PATH" OPENSWARM_LINK_TIMEOUT_S=2 "$openswarm" experiment experiments/qemu.json --out results \
    >hung.log 2>&1 || status=$?
test "$status" -eq 1 || fail "a hanging QEMU: exit $status, not 1" hung.log
grep -q "^2 of 4 trials done (2 by an earlier run), 2 failed" hung.log &&
    grep -q "robot 0's controller .*/clusters.elf did not answer .* within 2 s of wall time" results/trials.csv ||
    fail "the hanging QEMU's trials" hung.log results/trials.csv

# The same command with QEMU: only the failed trials run.
"$openswarm" experiment experiments/qemu.json --out results >good.log 2>&1 || fail "the sweep" good.log
grep -q "^4 of 4 trials done (2 by an earlier run), 0 failed" good.log || fail "the resumed sweep" good.log
grep -q '"fidelity": "qemu"' results/point-03/trial-01/world.json || fail "a qemu trial's world" results/point-03/trial-01/world.json
test "$(ls build/epuck_world-qemu/clusters.elf build/epuck_world-qemu/clusters-plain.elf | wc -l)" -eq 2 ||
    fail "the QEMU images" good.log
for pair in "01 03" "02 04"; do
    set -- $pair
    for f in trajectories.csv objects.csv metrics.csv; do
        cmp "results/point-$1/trial-01/$f" "results/point-$2/trial-01/$f" ||
            fail "point $2 (qemu) recorded $f as point $1 (exact) did"
    done
done
python3 - results/results.csv <<'PY' || fail "results.csv: the qemu points' values are the exact ones'" results/results.csv
import csv, sys
by = {}
for r in csv.DictReader(open(sys.argv[1])):
    by.setdefault(r["fidelity"], {})[(r["program"], r["time_s"], r["metric"])] = r["value"]
assert set(by) == {"exact", "qemu"}, set(by)
assert by["exact"] == by["qemu"], sorted(set(by["exact"].items()) ^ set(by["qemu"].items()))[:4]
assert len(by["qemu"]) == 2 * 2 * 41, len(by["qemu"])  # 2 programs x 2 metrics x samples 0..4 s
PY
# A world of its own with "fidelity": "qemu": `openswarm run --world`
# builds and runs the image alike (point 3's trial: the app's image).
"$openswarm" run --world results/point-03/trial-01/world.json --out run >run.log 2>&1 || fail "run --world" run.log
cmp run/trajectories.csv results/point-03/trial-01/trajectories.csv || fail "run --world: the trial's record" run.log
echo "$passed checks passed"
test "$failed" -eq 0
echo "a sweep's qemu points record what its exact ones do"
