#!/usr/bin/env bash
# End to end: the build tells the truth about memory, and writes what goes
# to the robot (issue 13).
#  - a thread stack the RAM cannot hold: refused by the configuration's
#    checks (exit 2, naming the key);
#  - the app's variables on top of it: "RAM overflow by N bytes" naming
#    the stack pool and the thread, not the linker's raw text alone;
#  - variables that leave the main stack too little: a warning, and the
#    simulator's measure of its worst use;
#  - an image that fits the ATmega328P's 32 KB but not the 28 KB below the
#    Kilobot's bootloader: "flash overflow by N bytes ... 0x7000";
#  - the .hex KiloGUI uploads: flash only (no .mmcu record at 0x910000),
#    and it runs in the simulator as the ELF does; an ELF without the MCU
#    record (a classic Makefile's) runs too, said once;
#  - `openswarm size` measures the main stack's and the thread's worst use
#    in the simulator.
#   honest_limits.sh OPENSWARM SIMULATOR WORKDIR
set -euo pipefail
openswarm=$1 sim=$2 work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work"
"$openswarm" new app --template blinky >/dev/null
cd app
stack() { sed -i "s/\"stack\": [0-9]*/\"stack\": $1/" openswarm.json; grep -q "\"stack\": $1" openswarm.json; }
expect_build_failure() {
  local status=0
  "$openswarm" build > build.log 2>&1 || status=$?
  test "$status" -eq 1 || { cat build.log; echo "FAILED: build exited $status, not 1"; exit 1; }
}

# A stack the RAM cannot hold is refused by the configuration's checks.
stack 2000
status=0
"$openswarm" build > build.log 2>&1 || status=$?
test "$status" -eq 2 && grep -Eq '"threads\[0\].stack": .*more than the kilobot.s 2048 of RAM' build.log \
  || { cat build.log; echo "FAILED: a 2000-byte stack was not refused (exit $status)"; exit 1; }

# The app's own variables come on top of what openswarm.json declares: the
# link finds them, and the tool explains it.
stack 96
cp main.c main.c.orig
big() { cp main.c.orig main.c; sed -i "s|^void blinker(void) {|volatile uint8_t big[$1];\n\nvoid blinker(void) {\n    big[0]++;|" main.c; }
big 2000
expect_build_failure
grep -Eq '^openswarm: RAM overflow by [0-9]+ bytes: .*the thread stack pool, [0-9]+ bytes \(openswarm.json.s "stack": blinker 96' build.log \
  || { cat build.log; echo "FAILED: no RAM overflow explanation"; exit 1; }

big 1150
"$openswarm" build > build.log 2>&1
grep -Eq '^openswarm: warning: RAM leaves the main stack [0-9]+ bytes, less than the 128' build.log \
  || { cat build.log; echo "FAILED: no main stack warning"; exit 1; }
"$sim" -q --main-stack --time 2 build/kilobot/app.elf 2> sim.log
grep -Eq '^openswarm-sim: main stack: worst use [1-9][0-9]* of [0-9]+ bytes$' sim.log \
  || { cat sim.log; echo "FAILED: no main stack measure"; exit 1; }

cp main.c.orig main.c
# 24000 bytes of table: with the kernel, over 28672 but under 32768.
sed -i 's|^void blinker(void) {|#include <avr/pgmspace.h>\nconst uint8_t table[24000] PROGMEM = {1};\nvolatile uint16_t at;\n\nvoid blinker(void) {\n    if (pgm_read_byte(\&table[at])) at++;|' main.c
grep -q "table\[24000\]" main.c
expect_build_failure
grep -Eq '^openswarm: flash overflow by [0-9]+ bytes: the image does not fit the 28672 bytes .*bootloader starts at 0x7000' build.log \
  || { cat build.log; echo "FAILED: no flash overflow explanation"; exit 1; }

cp main.c.orig main.c
"$openswarm" build > build.log 2>&1
test -s build/kilobot/app.hex
# Records of type 04 set the upper address: the .mmcu record would need 0x0091.
! grep -q '^:02000004' build/kilobot/app.hex || { echo "FAILED: the .hex carries more than flash"; exit 1; }
"$sim" --trace --time 1 build/kilobot/app.elf > elf.log 2>&1
"$sim" --trace --time 1 build/kilobot/app.hex > hex.log 2>&1
grep -q "has no MCU record: running it as a Kilobot's ATmega328P at 8 MHz" hex.log
diff <(grep '\] led' elf.log) <(grep '\] led' hex.log)
test "$(grep -c '\] led' hex.log)" -ge 3
avr-objcopy -R .mmcu build/kilobot/app.elf classic.elf
"$sim" --trace --time 1 classic.elf > classic.log 2>&1
grep -q "classic.elf has no MCU record: running it as a Kilobot's ATmega328P at 8 MHz" classic.log
diff <(grep '\] led' elf.log) <(grep '\] led' classic.log)
"$openswarm" size > size.log 2>&1
grep -Eq '^Main stack \(main, interrupts, event handlers\): worst use [1-9][0-9]* of its [0-9]+ bytes in 5 s in the simulator$' size.log \
  || { cat size.log; echo "FAILED: size does not measure the main stack"; exit 1; }
grep -Eq '^  blinker +[1-9][0-9]* of +172$' size.log \
  || { cat size.log; echo "FAILED: size does not measure the thread's stack"; exit 1; }
echo "honest limits: 9 passed, 0 failed"
