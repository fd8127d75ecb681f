#!/usr/bin/env bash
# End to end: `openswarm test --record NAME -- OPTIONS` writes
# tests/NAME.trace from a run - what the robots did and what they printed -
# and `openswarm test` then checks both: it passes as recorded, and fails,
# naming the line, when a console line is not printed; recording over a
# test needs --force; a bad name is refused.
#   test_record.sh OPENSWARM WORKDIR
set -euo pipefail
openswarm=$1 work=$2
rm -rf "$work" && mkdir -p "$work" && cd "$work"
"$openswarm" new app --template threads-and-events >/dev/null
cd app
"$openswarm" test --record boot -- --time 1.2 > record.log
grep -Eq "^Recorded ./tests/boot.trace: [1-9][0-9]* changes, [1-9][0-9]* console lines" record.log
grep -q "^# run: --time 1.2$" tests/boot.trace
grep -Eq "^> [0-9]+:\([0-9]+,[0-9]+\) primes [0-9]+$" tests/boot.trace
grep -Eq "^[0-9]+\.[0-9]{3},motors,[0-9]+,[0-9]+,0$" tests/boot.trace
"$openswarm" test > test.log
grep -Eq "^boot +PASSED$" test.log
# A console line the firmware never prints fails the test, naming its line.
line=$(grep -n "^> " tests/boot.trace | head -1 | cut -d: -f1)
sed -i "${line}s/primes/prime numbers/" tests/boot.trace
status=0
"$openswarm" test > fail.log 2>&1 || status=$?
test "$status" -eq 1
grep -q "tests/boot.trace:${line}: expected the console line '.*prime numbers.*', not printed" fail.log
grep -Eq "^boot +FAILED$" fail.log
status=0
"$openswarm" test --record boot -- --time 1 2> again.log || status=$?
test "$status" -eq 2 && grep -q "tests/boot.trace exists: pass --force to record it again" again.log
"$openswarm" test --record boot --force -- --time 1.2 > /dev/null
"$openswarm" test > test.log
grep -Eq "^boot +PASSED$" test.log
status=0
"$openswarm" test --record "no good" 2> name.log || status=$?
test "$status" -eq 2 && grep -q "a test's name is letters, digits, - and _" name.log
echo "1 passed, 0 failed"
