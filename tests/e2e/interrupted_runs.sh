#!/usr/bin/env bash
# End to end: Ctrl-C (SIGINT) or SIGTERM sent to the tool while it runs
# (issue 30, "every output is whole or absent"):
#   openswarm run --world: the signal reaches the simulator, which writes
#   the run so far; exit 130 / 143, a line naming the time and the folder,
#   trajectories.csv ending on a whole record, final.png, viewer.html;
#   openswarm experiment (a clustering experiment with a stand-in e-puck
#   controller): the trial running stops and is not run yet, the finished
#   one kept, exit 130; the same command again resumes, and its results
#   are those of a run never interrupted, byte for byte.
# Each signal is sent once the run is under way (a file or a progress
# line seen), not after a fixed sleep.
#   interrupted_runs.sh OPENSWARM DOUBLE.py WORKDIR
set -uo pipefail
openswarm=$1 double=$2 work=$3 here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work" && mkdir -p "$work" && cd "$work"
source "$here/check.sh"
count_failure() { failed=$((failed + 1)); echo "FAILED: $1"; shift; for f in "$@"; do echo "--- $f"; cat "$f"; done; }
holds() { local what=$1; shift; if "$@"; then passed=$((passed + 1)); else count_failure "$what"; fi; }

# wait_for TEST...: until the test holds (at most 600 s: the app's build
# comes first, on a loaded machine).
wait_for() {
    for _ in $(seq 6000); do "$@" && return 0; sleep 0.1; done
    return 1
}

# with_sigint COMMAND...: runs it with SIGINT as from a terminal: a
# script's background job starts with SIGINT ignored, which the tool and
# the simulator keep as they found it. exec: $! is then the tool's pid.
with_sigint() {
    exec python3 -c 'import os, signal, sys; signal.signal(signal.SIGINT, signal.SIG_DFL); os.execvp(sys.argv[1], sys.argv[1:])' "$@"
}

# interrupt PID SIGNAL: sends it, waits for the end; the exit status.
interrupt() {
    kill "-$2" "$1"
    wait "$1"
}

# whole_run DIR: trajectories.csv ends on a whole 8-column record; final.png
# is a PNG; viewer.html ends with </html>; no .part left.
whole_run() {
    local dir=$1
    [ "$(tail -c 1 "$dir/trajectories.csv" | od -An -c | tr -d ' ')" = '\n' ] &&
        [ "$(tail -n 1 "$dir/trajectories.csv" | awk -F, '{print NF}')" -eq 8 ] &&
        head -c 8 "$dir/final.png" | od -An -tx1 | grep -q "89 50 4e 47 0d 0a 1a 0a" &&
        [ "$(tail -n 1 "$dir/viewer.html")" = "</html>" ] &&
        ! ls "$dir"/*.part >/dev/null 2>&1
}

# ---- openswarm run --world, SIGINT then SIGTERM
"$openswarm" new app --template disperse >/dev/null || count_failure "openswarm new"
for signal in INT TERM; do
    out=out-$signal
    with_sigint "$openswarm" run -C app --world app/worlds/packed.json --time 3000 --out "$out" >"run-$signal.log" 2>&1 &
    pid=$!
    wait_for test -s "$out/trajectories.csv.part" || count_failure "run $signal never got under way" "run-$signal.log"
    interrupt "$pid" "$signal"
    status=$?
    want=$((128 + $(kill -l "$signal")))
    holds "run: SIG$signal gave $status, not $want" test "$status" -eq "$want"
    holds "run: SIG$signal: no line with the time" \
        grep -Eq "openswarm-sim: interrupted by SIG$signal at [0-9]+\.[0-9]{3} s of simulated time: wrote the run up to then to $out/trajectories.csv" "run-$signal.log"
    holds "run: SIG$signal: no line saying where the outputs are" \
        grep -q "openswarm: interrupted by SIG$signal at the simulated time .*; outputs written to $out (open $out/viewer.html)" "run-$signal.log"
    holds "run: SIG$signal: the outputs are not whole" whole_run "$out"
    [ "$failed" -eq 0 ] || cat "run-$signal.log"
done

# ---- openswarm experiment: interrupted, then resumed
cp "$double" controller.py && chmod +x controller.py
cat > clustering.json <<'JSON'
{
  "arena": {"width_mm": 1000, "height_mm": 1000},
  "marks": {"columns": 3, "rows": 3, "spacing_mm": 250},
  "robots": 2,
  "objects": {"count": 3},
  "duration_s": 300,
  "trials": 3,
  "controllers": [{"name": "double", "program": "controller.py"}]
}
JSON
export EPUCK_WHEELS=300,200
"$openswarm" experiment clustering.json --out whole -j 1 >whole.log 2>&1 || count_failure "the uninterrupted experiment" whole.log
with_sigint "$openswarm" experiment clustering.json --out resumed -j 1 >first.log 2>&1 &
pid=$!
wait_for grep -q '^\[1/3\] double, trial 1: largest cluster' first.log || count_failure "the experiment never finished a trial" first.log
interrupt "$pid" INT
status=$?
holds "experiment: SIGINT gave $status, not 130" test "$status" -eq 130
holds "experiment: no line saying what is pending and how to resume" \
    grep -q "openswarm: interrupted by SIGINT: 2 trials not run yet; .*Run the same command again to resume" first.log
holds "experiment: the stopped trial was not recorded as not run yet" \
    grep -q '^\[stopped\] double, trial 2: not run yet (interrupted)' first.log
holds "experiment: trial 1's outcome was not kept" test -s resumed/trial-01-double/outcome.json
holds "experiment: the stopped trial has an outcome" test ! -e resumed/trial-02-double/outcome.json
holds "experiment: results.csv is not trial 1's alone" \
    test "$(cut -d, -f1 resumed/results.csv | sort -u | tr '\n' ' ')" = "1 trial "
"$openswarm" experiment clustering.json --out resumed -j 1 >second.log 2>&1 || count_failure "the resumed experiment" second.log
holds "experiment: trial 1 was run again" grep -q '^\[1/3\] double, trial 1: done before, ' second.log
holds "experiment: the resumed results differ from the uninterrupted run's" cmp -s whole/results.csv resumed/results.csv
[ "$failed" -eq 0 ] || cat first.log second.log

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
