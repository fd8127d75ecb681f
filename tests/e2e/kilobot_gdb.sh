#!/usr/bin/env bash
# End to end: `openswarm run --debug --gdb PORT` builds the debug image
# (-Og, no link-time optimisation) and waits for avr-gdb, which stops at a
# line of the app's own source, reads a variable there, lists the source
# and ends the run. The release image (LTO) has no line table for this.
#   kilobot_gdb.sh OPENSWARM WORKDIR PORT
set -euo pipefail
openswarm=$1 work=$2 port=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work"
"$openswarm" new app --template blinky >/dev/null
cd app
line=$(grep -n '^    blinks++;$' main.c | cut -d: -f1)
test -n "$line"
"$openswarm" build --debug > build.log
grep -q "Built ./build/kilobot-debug/app.elf for kilobot" build.log
"$openswarm" run --debug --gdb "$port" --time 3 > run.log 2>&1 &
run_pid=$!
for _ in $(seq 200); do grep -q "waiting for avr-gdb" run.log && break; sleep 0.1; done
grep -q "avr-gdb -ex 'target remote :$port' ./build/kilobot-debug/app.elf" run.log
# The handler counts a blink per LED period: at the second stop it has
# counted one.
timeout 60 avr-gdb -batch -nx build/kilobot-debug/app.elf -ex "target remote :$port" \
    -ex "break main.c:$line" -ex "continue" -ex "continue" -ex "print blinks" -ex "list $line,$line" \
    -ex "kill" > gdb.log 2>&1 || true
cat gdb.log
grep -Eq "^Breakpoint 1, count_blink \(.*\) at .*/app/main.c:$line$" gdb.log
grep -q '^\$1 = 1$' gdb.log
grep -Eq "^$line[[:space:]]+blinks\+\+;$" gdb.log
wait "$run_pid" # after the debugger leaves, the firmware runs on to the end
grep -q "ran 3.000 s of simulated time" run.log
echo "1 passed, 0 failed"
