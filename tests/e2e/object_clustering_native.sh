#!/usr/bin/env bash
# End to end: the case study in the native mode. The object-clustering
# template is built for the world twice - its controllers as programs (the
# pipe mode) and with --native as shared objects - and a short experiment
# (2 trials x 1 simulated minute per controller) runs both ways: the pipe
# mode is deterministic for a seed, so the native run's results.csv must be
# the same, byte for byte. An experiment file's "fidelity" asks for the
# native mode as --native does; a native controller not built yet, an
# unknown fidelity and --native on a sweep are refused with the fix.
#   object_clustering_native.sh OPENSWARM WORKDIR
set -euo pipefail
openswarm=$1 work=$2
rm -rf "$work" && mkdir -p "$work" && cd "$work"
"$openswarm" new clusters --template object-clustering > new.log
cd clusters
# Refused before anything is built: the native controllers are not there.
status=0; "$openswarm" experiment experiments/paper.json --native --trials 1 --duration 10 2> unbuilt.log || status=$?
test "$status" -eq 2 && grep -q 'build/epuck_world-native/clusters.so does not exist: build it first (openswarm build --port epuck_world --native in its app)' unbuilt.log
"$openswarm" build > build.log
"$openswarm" build --native > native-build.log
test -s build/epuck_world-native/clusters.so && test -s build/epuck_world-native/clusters-plain.so
"$openswarm" experiment experiments/paper.json --trials 2 --duration 60 --out pipe > pipe.log
"$openswarm" experiment experiments/paper.json --trials 2 --duration 60 --native --out native > native.log
cat native.log
grep -q '"fidelity": "native"' native/trial-01-openswarm/world.json
cmp pipe/results.csv native/results.csv
# The file's own setting does what --native does.
sed 's|"trials": 10,|"trials": 10, "fidelity": "native",|' experiments/paper.json > experiments/native.json
"$openswarm" experiment experiments/native.json --trials 1 --duration 60 --out by-file > by-file.log
grep -q '"fidelity": "native"' by-file/trial-01-openswarm/world.json
# Refusals: exit 2, the file or option, and the fix.
sed 's|"trials": 10,|"trials": 10, "fidelity": "fast",|' experiments/paper.json > experiments/fast.json
status=0; "$openswarm" experiment experiments/fast.json 2> fast.log || status=$?
test "$status" -eq 2 && grep -q 'unknown fidelity "fast"; known: exact' fast.log
echo "1 passed, 0 failed"
