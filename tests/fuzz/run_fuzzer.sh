#!/usr/bin/env bash
# Run a fuzzer for a fixed number of inputs from its seeds (not for a
# time: the same inputs on any machine). Every run starts from the seeds
# alone: the corpus it grows lives in a temporary folder removed at exit,
# so a second ctest run in the same build folder fuzzes as a fresh clone's
# first would. Any crash, leak, sanitizer report or escaping exception
# fails it, and the input that did it is kept in WORKDIR (libFuzzer's
# "Test unit written to WORKDIR/crash-..." line names it).
#   run_fuzzer.sh FUZZER SEEDS WORKDIR RUNS
set -euo pipefail
fuzzer=$1 seeds=$2 work=$3 runs=$4
rm -rf "$work" && mkdir -p "$work"
corpus=$(mktemp -d "${TMPDIR:-/tmp}/openswarm-corpus.XXXXXX")
trap 'rm -rf "$corpus"' EXIT
cd "$work"
"$fuzzer" -runs="$runs" -seed=1 -close_fd_mask=3 -artifact_prefix="$work/" "$corpus" "$seeds"
