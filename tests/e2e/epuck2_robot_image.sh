#!/usr/bin/env bash
# The e-puck2's robot image: `openswarm build` of a template for epuck2
# also builds <app>-robot.elf and .bin; they must be what the robot's flash
# takes after its bootloader: linked at 0x08020000 (the vector table's
# first word an initial stack pointer in RAM, its reset vector a Thumb
# address inside the image), no semihosting trap (BKPT 0xAB is a HardFault
# on a robot without a debugger), and the robot board's drivers in it (the
# vector table pointing at their interrupt handlers).
#   epuck2_robot_image.sh OPENSWARM WORKDIR TEMPLATE
set -euo pipefail
openswarm=$1 work=$2 template=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work"
"$openswarm" new app --template "$template" --port epuck2
cd app
"$openswarm" build | tee build.log
elf=build/epuck2/app-robot.elf bin=build/epuck2/app-robot.bin
test -s "$elf" && test -s "$bin"
grep -q "^Robot image (flash from 0x08020000, after the bootloader):$" build.log
grep -Eq "^Built ./build/epuck2/app-robot.elf and ./build/epuck2/app-robot.bin" build.log
# Its size, against the 896 KB the bootloader leaves.
grep -A1 "^Robot image" build.log | grep -Eq "^Flash \[.*\] +[0-9.]+% \([1-9][0-9]* of 917504 bytes\)$"
"$openswarm" build --json > build.json
python3 - "$elf" "$bin" build.json <<'PY'
import json, struct, subprocess, sys
elf, binary, result = sys.argv[1:4]
j = json.load(open(result))
assert j["robot"]["image"].endswith("app-robot.elf") and 0 < j["robot"]["flash"] <= j["flash_total"] == 917504, j

def fail(why):
    sys.exit("FAILED: " + elf + ": " + why)

# Where the image is linked: the first loadable segment at 0x08020000.
headers = subprocess.run(["arm-none-eabi-readelf", "-lW", elf], capture_output=True, text=True, check=True).stdout
loads = [l.split() for l in headers.splitlines() if l.strip().startswith("LOAD")]
first_flash = min(int(l[2], 16) for l in loads)  # physical (load) addresses
if first_flash != 0x08020000:
    fail("linked at 0x%08x, not 0x08020000 (after the e-puck2's 128 KB bootloader)" % first_flash)
image = open(binary, "rb").read()
sp, reset = struct.unpack_from("<II", image, 0)
if not 0x20000000 < sp <= 0x20020000:
    fail("vector 0 (initial SP) 0x%08x is not in the 128 KB of SRAM" % sp)
if not (reset & 1 and 0x08020000 <= reset & ~1 < 0x08020000 + len(image)):
    fail("reset vector 0x%08x is not a Thumb address inside the image (0x08020000 + %d bytes)" % (reset, len(image)))

# No semihosting: no BKPT 0xAB anywhere in the code.
code = subprocess.run(["arm-none-eabi-objdump", "-d", elf], capture_output=True, text=True, check=True).stdout
traps = [l for l in code.splitlines() if "bkpt" in l and "0x00ab" in l.replace("0xab", "0x00ab")]
if traps:
    fail("semihosting trap(s) in the robot image:\n" + "\n".join(traps))

# The drivers are in, their handlers in the vector table (weak defaults
# would be left if the drivers were not linked).
symbols = {}
for line in subprocess.run(["arm-none-eabi-nm", elf], capture_output=True, text=True, check=True).stdout.splitlines():
    parts = line.split()
    if len(parts) == 3:
        symbols[parts[2]] = int(parts[0], 16)
vectors = struct.unpack_from("<98I", image, 0)
for irq, handler in [(29, "TIM3_IRQHandler"), (30, "TIM4_IRQHandler"), (28, "TIM2_IRQHandler"), (18, "ADC_IRQHandler"),
                     (55, "TIM7_IRQHandler"), (57, "DMA2_Stream1_IRQHandler"), (78, "DCMI_IRQHandler"),
                     (39, "USART3_IRQHandler"), (54, "TIM6_DAC_IRQHandler")]:
    if handler not in symbols:
        fail(handler + " is not in the image")
    if vectors[16 + irq] & ~1 != symbols[handler]:
        fail("vector %d is 0x%08x, not %s (0x%08x)" % (16 + irq, vectors[16 + irq], handler, symbols[handler]))
for text in [b"never became ready", b"the PLL never locked"]:  # the clock tree's reports
    if text not in image:
        fail("the clock tree's report %r is not in the image" % text)
print("robot image: linked at 0x08020000, SP 0x%08x, reset 0x%08x, %d bytes, no BKPT 0xAB, 9 handlers" % (sp, reset, len(image)))
PY
# The semihosting check does see a trap: QEMU's image has them.
arm-none-eabi-objdump -d build/epuck2/app.elf > qemu.dis
grep -q "bkpt.*0x00ab" qemu.dis
echo "1 passed, 0 failed"
