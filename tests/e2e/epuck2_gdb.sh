#!/usr/bin/env bash
# End to end: `openswarm run --gdb PORT` on the e-puck2 under QEMU waits for
# gdb-multiarch, which stops at a line of the app's source, steps, reads a
# variable, and ends the run (which then does not claim to have run).
#   epuck2_gdb.sh OPENSWARM WORKDIR PORT
set -euo pipefail
openswarm=$1 work=$2 port=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work"
"$openswarm" new app --template blinky --port epuck2 >/dev/null
cd app
"$openswarm" build >/dev/null
status=0
"$openswarm" run --gdb "$port" --time 2 > run.log 2>&1 &
run_pid=$!
for _ in $(seq 100); do grep -q "QEMU waits for the debugger" run.log && break; sleep 0.1; done
grep -q "gdb-multiarch ./build/epuck2/app.elf -ex 'target remote :$port'" run.log
sleep 0.5 # QEMU opens its gdb port after it starts
timeout 60 gdb-multiarch -batch -nx build/epuck2/app.elf -ex "target remote :$port" \
    -ex "break blinker" -ex "continue" -ex "next" -ex "info line *\$pc" -ex "print blinks" \
    -ex "kill" > gdb.log 2>&1
cat gdb.log
grep -Eq "^Breakpoint 1, .*blinker \(\) at .*/app/main.c:[0-9]+" gdb.log
grep -Eq "^Line [0-9]+ of \".*/app/main.c\"" gdb.log
grep -q '^\$1 = 0$' gdb.log
wait "$run_pid" || status=$?
cat run.log
test "$status" -eq 1
grep -q "openswarm: the run ended before 2 s of simulated time: main returned 0 (a firmware should not return), or the debugger ended it" run.log
echo "1 passed, 0 failed"
