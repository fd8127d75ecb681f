#!/usr/bin/env bash
# End to end: an experiment spread over two MPI ranks on one machine
# (`mpirun -np 2 --oversubscribe openswarm experiment FILE`) gives the same
# results.csv, byte for byte, as the same experiment run alone: each rank
# runs its share of the trials (both controllers on each), rank 0 gathers.
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
echo "1 passed, 0 failed"
