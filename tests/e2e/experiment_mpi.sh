#!/usr/bin/env bash
# End to end: an experiment spread over two MPI ranks on one machine
# (`mpirun -np 2 --oversubscribe openswarm experiment FILE`) gives the same
# results.csv, byte for byte, as the same experiment run alone: each rank
# runs its share of the trials (both controllers on each), rank 0 gathers;
# a trial that fails on rank 1 is reported by rank 0 with its whole reason.
#   experiment_mpi.sh OPENSWARM WORKDIR
set -euo pipefail
openswarm=$1 work=$2
rm -rf "$work" && mkdir -p "$work" && cd "$work"
"$openswarm" new clusters --template object-clustering > /dev/null
cd clusters
"$openswarm" build > build.log
# Open MPI refuses root unless told; CI machines run the suite as root.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mpirun --oversubscribe -np 2 "$openswarm" experiment experiments/paper.json --trials 3 --duration 60 \
    --out mpi > mpi.log 2>&1 || { cat mpi.log; echo "FAILED: mpirun exited $?"; exit 1; }
cat mpi.log
grep -q "on each of 2 ranks" mpi.log
test "$(grep -c '^\[rank 0 ' mpi.log)" -eq 3 && test "$(grep -c '^\[rank 1 ' mpi.log)" -eq 3
grep -q "^\[rank 0 .*OpenSwarm" mpi.log && grep -q "^\[rank 1 .*OpenSwarm" mpi.log
grep -Eq "^6 of 6 trials ran in " mpi.log
"$openswarm" experiment experiments/paper.json --trials 3 --duration 60 --out alone > alone.log
cmp mpi/results.csv alone/results.csv
# The summary table: each controller's largest cluster and compactness at
# the end, the mean +- sample SD of its trials' last rows in results.csv.
python3 - alone/results.csv alone.log <<'TABLE'
import csv, statistics, sys
rows = list(csv.DictReader(open(sys.argv[1])))
end = max(float(r["time_s"]) for r in rows)
table = open(sys.argv[2]).read()
for name in sorted({r["controller"] for r in rows}):
    last = [r for r in rows if r["controller"] == name and float(r["time_s"]) == end]
    cluster = [100 * float(r["largest_cluster"]) for r in last]
    compact = [float(r["compactness"]) for r in last]
    line = next(l for l in table.splitlines() if l.startswith(name + "  "))
    f = line[len(name):].replace("%", "").replace("+-", " ").split()
    want = [statistics.mean(cluster), statistics.stdev(cluster), statistics.mean(compact), statistics.stdev(compact)]
    got = [float(x) for x in f[2:6]]
    if any(abs(g - w) > 0.06 for g, w in zip(got, want)):
        sys.exit(f"FAILED: {name}'s row {line!r}: expected the end's mean +- SD {want}")
TABLE

# A trial that fails on rank 1 (slot = trial + controller: the second
# controller's first trial) reaches rank 0 with its reason whole, newlines
# and tabs included (one such reason crashed rank 0: std::stoul on a line
# of it), and the other trial's results are kept.
cat > broken.sh <<'BROKEN'
#!/bin/sh
printf 'broken on purpose:\n\tline two\twith tabs\n7\tnot a trial\n' >&2
exit 1
BROKEN
chmod +x broken.sh
python3 - <<'SPEC'
import json
e = json.load(open("experiments/paper.json"))
e["controllers"] = [e["controllers"][0], {"name": "broken", "program": "../broken.sh"}]
json.dump(e, open("experiments/broken.json", "w"), indent=1)
SPEC
status=0
mpirun --oversubscribe -np 2 "$openswarm" experiment experiments/broken.json --trials 1 --duration 10 \
    --out broken > broken.log 2>&1 || status=$?
cat broken.log
test "$status" -eq 1 || { echo "FAILED: mpirun exited $status, not 1 (a failed trial)"; exit 1; }
grep -Eq "^1 of 2 trials ran in " broken.log
grep -q "broken, trial 1 (.*) failed: " broken.log
grep -q "^broken on purpose:$" broken.log
grep -q "^$(printf '\t')line two$(printf '\t')with tabs$" broken.log
grep -q "^7$(printf '\t')not a trial$" broken.log
grep -q "^1,OpenSwarm,.*,10.000," broken/results.csv
echo "2 passed, 0 failed"
