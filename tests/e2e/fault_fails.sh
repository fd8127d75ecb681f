#!/usr/bin/env bash
# End to end: a firmware whose thread overflows its stack fails `openswarm
# run` and `openswarm test` (it used to pass them: "1 passed, 0 failed",
# exit 0, the fault printed after the table), saying which thread and when;
# one whose thread returns into its stack's paint (PC past the flash) fails
# `openswarm run` as a crash (the simulator died of SIGSEGV, exit 139).
#   fault_fails.sh OPENSWARM WORKDIR
set -euo pipefail
openswarm=$1 work=$2
rm -rf "$work" && mkdir -p "$work" && cd "$work"

# openswarm ARGS... into LOG, shown: it must fail (exit 1).
fails() {
    local log=$1 status=0
    shift
    "$openswarm" "$@" > "$log" 2>&1 || status=$?
    cat "$log"
    test "$status" -eq 1 || { echo "FAILED: openswarm $1 exited $status, not 1"; exit 1; }
}

"$openswarm" new app --template blinky >/dev/null
cd app
cp main.c main.c.orig
# 200 bytes on a thread whose stack is 96 (openswarm.json).
sed -i 's|    for (;;) {|    volatile uint8_t big[200];\n    for (uint8_t i = 0; i < sizeof big; i++) big[i] = i;\n    for (;;) {|' main.c
grep -q "volatile uint8_t big\[200\]" main.c
fails run.log run --time 1
grep -Eq "^openswarm-sim: kernel fault: stack overflow in thread [0-9]+ \(blinker\) at 0\.[0-9]+ s: give the thread a bigger \"stack\" in openswarm.json$" run.log
grep -q "^openswarm: the firmware reported a kernel fault, a stack overflowed or a pointer wrote into the CPU's registers (above: which, when, and what to do): the run fails$" run.log
fails test.log test
grep -Eq "^blinks +FAILED$" test.log
grep -q "^0 passed, 1 failed$" test.log
grep -q "the firmware reported a kernel fault" test.log

# SP 30 bytes down, then ret: the return address is the kernel's paint of
# the thread's stack, 0xE7E7, a PC of 0x1cfce, past the 32 KB of flash.
cp main.c.orig main.c
sed -i 's|^void blinker(void) {|void blinker(void) {\n    __asm__ volatile("in r26, __SP_L__\\n\\tin r27, __SP_H__\\n\\tsbiw r26, 30\\n\\t"\n                     "out __SP_H__, r27\\n\\tout __SP_L__, r26\\n\\tret" ::: "r26", "r27");|' main.c
grep -q "sbiw r26, 30" main.c
fails crash.log run --time 1
grep -Eq "^openswarm-sim: robot 0 \(.*app\.elf\) crashed at 0\.[0-9]+ s: its program counter left the flash: PC 0x1cfce, past its end at 0x7fff" crash.log
grep -q "^openswarm: the firmware crashed (above)" crash.log
echo "1 passed, 0 failed"
