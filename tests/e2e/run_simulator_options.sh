#!/usr/bin/env bash
# End to end: `openswarm run` hands the simulator what it is given - the
# overhead controller's messages, the profiler, and anything after --.
#   run_simulator_options.sh OPENSWARM WORKDIR
set -euo pipefail
openswarm=$1 work=$2
rm -rf "$work" && mkdir -p "$work" && cd "$work"
"$openswarm" new app --template kilolib >/dev/null
cd app
# The template blinks blue; SLEEP at 0.5 s stops the program, so the LED
# changes no more after it.
"$openswarm" run --time 1.5 --ohc sleep@0.5 --profile -- --uid 7 >run.log 2>&1
grep -q "profile of [0-9]* cycles, by function" run.log
grep -q "(asleep)" run.log
last=$(grep -o "^\[ *[0-9.]* s\] led" run.log | tail -1 | grep -o "[0-9.]*" | head -1)
awk -v t="$last" 'BEGIN { exit !(t <= 0.55) }' || { echo "the LED changed at $last s, after SLEEP"; cat run.log; exit 1; }
# Something the simulator refuses is reported with its own message.
if "$openswarm" run --time 1 -- --light nonsense >bad.log 2>&1; then
    echo "a bad simulator option was accepted"; cat bad.log; exit 1
fi
grep -q -- "--light 'nonsense'" bad.log
echo "1 passed, 0 failed"
