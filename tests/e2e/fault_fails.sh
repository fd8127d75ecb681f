#!/usr/bin/env bash
# End to end: a firmware whose thread overflows its stack fails `openswarm
# run` and `openswarm test` (it used to pass them: "1 passed, 0 failed",
# exit 0, the fault printed after the table), saying which thread and when.
#   fault_fails.sh OPENSWARM WORKDIR
set -euo pipefail
openswarm=$1 work=$2
rm -rf "$work" && mkdir -p "$work" && cd "$work"
"$openswarm" new app --template blinky >/dev/null
cd app
# 200 bytes on a thread whose stack is 96 (openswarm.json).
sed -i 's|    for (;;) {|    volatile uint8_t big[200];\n    for (uint8_t i = 0; i < sizeof big; i++) big[i] = i;\n    for (;;) {|' main.c
grep -q "volatile uint8_t big\[200\]" main.c
status=0
"$openswarm" run --time 1 > run.log 2>&1 || status=$?
cat run.log
test "$status" -eq 1 || { echo "FAILED: run exited $status, not 1"; exit 1; }
grep -Eq "^openswarm-sim: kernel fault: stack overflow in thread [0-9]+ \(blinker\) at 0\.[0-9]+ s$" run.log
grep -q "^openswarm: the firmware reported a kernel fault, a stack overflowed or a pointer wrote into the CPU's registers (above: which, when): the run fails" run.log
status=0
"$openswarm" test > test.log 2>&1 || status=$?
cat test.log
test "$status" -eq 1 || { echo "FAILED: test exited $status, not 1"; exit 1; }
grep -Eq "^blinks +FAILED$" test.log
grep -q "^0 passed, 1 failed$" test.log
grep -q "the firmware reported a kernel fault" test.log
echo "1 passed, 0 failed"
