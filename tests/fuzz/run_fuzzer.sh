#!/usr/bin/env bash
# Run a fuzzer for a fixed number of inputs from its seeds (not for a
# time: the same inputs on any machine), in a fresh corpus folder; any
# crash, leak, sanitizer report or escaping exception fails it, and the
# input that did it is kept in the corpus folder's parent.
#   run_fuzzer.sh FUZZER SEEDS WORKDIR RUNS
set -euo pipefail
fuzzer=$1 seeds=$2 work=$3 runs=$4
rm -rf "$work" && mkdir -p "$work/corpus"
cd "$work"
"$fuzzer" -runs="$runs" -seed=1 -close_fd_mask=3 -artifact_prefix="$work/" corpus "$seeds"
