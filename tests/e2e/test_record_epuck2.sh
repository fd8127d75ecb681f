#!/usr/bin/env bash
# End to end: `openswarm test --record` from a QEMU run (the e-puck2's
# blinky): the trace holds the status light's changes, `openswarm test`
# passes it as recorded and fails, naming the line, once a value in it is
# made wrong; options QEMU does not take are refused (exit 2). Recording
# was refused for every port but the Kilobot's.
#   test_record_epuck2.sh OPENSWARM WORKDIR
set -euo pipefail
openswarm=$1 work=$2
rm -rf "$work" && mkdir -p "$work" && cd "$work"
"$openswarm" new app --template blinky --port epuck2 >/dev/null
cd app
"$openswarm" test --record blink -- --time 1.1 > record.log
grep -Eq "^Recorded ./tests/blink.trace: 5 changes, [0-9]+ console lines" record.log
grep -q "^# run: --time 1.1$" tests/blink.trace
grep -Eq "^0\.250,led,0,0,0$" tests/blink.trace
grep -Eq "^1\.000,led,0,3,0$" tests/blink.trace
"$openswarm" test > test.log
grep -Eq "^blink +PASSED$" test.log
# A wrong value fails the test, naming its line.
line=$(grep -n "^1\.000,led,0,3,0$" tests/blink.trace | cut -d: -f1)
sed -i "${line}s/^1\.000,led,0,3,0$/1.000,led,3,0,0/" tests/blink.trace
status=0
"$openswarm" test > fail.log 2>&1 || status=$?
test "$status" -eq 1 || { echo "FAILED: test of an edited trace exited $status"; cat fail.log; exit 1; }
grep -q "tests/blink.trace:${line}: expected robot 0 led 3 0 0 at 1.000 s, got robot 0 led 0 3 0 at 1.000 s" fail.log
grep -Eq "^blink +FAILED$" fail.log
status=0
"$openswarm" test --record more --force -- --robots 2 2> refused.log || status=$?
test "$status" -eq 2 && grep -q "^openswarm: --record on the epuck2 port: --robots: QEMU runs one robot, and of the run options takes only --time" refused.log
echo "1 passed, 0 failed"
