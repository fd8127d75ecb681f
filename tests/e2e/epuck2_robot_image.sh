#!/usr/bin/env bash
# The e-puck2's robot image: `openswarm build` of a template for epuck2
# also builds <app>-robot.elf and .bin; they must be what the robot's flash
# takes where openswarm.json's "epuck2": {"bootloader"} puts them: linked
# at 0x08000000 with the whole 1 MB for "none" (the default: a robot with
# GCtronic's standard firmware has no bootloader), at 0x08020000 with
# 896 KB for "aseba" (after the Aseba bootloader), the build saying which
# and counting the size against it; the vector table at that address (its
# first word an initial stack pointer in RAM, its reset vector the ELF's
# entry, inside the image), the .bin the raw flash from there; no
# semihosting trap (BKPT 0xAB is a HardFault on a robot without a
# debugger), and the robot board's drivers in it (the vector table
# pointing at their interrupt handlers). The QEMU image stays at
# 0x08000000 whatever the setting. A bad setting is refused with its key.
#   epuck2_robot_image.sh OPENSWARM WORKDIR TEMPLATE
set -euo pipefail
openswarm=$1 work=$2 template=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work"
"$openswarm" new app --template "$template" --port epuck2
cd app
cp openswarm.json openswarm.json.orig
elf=build/epuck2/app-robot.elf bin=build/epuck2/app-robot.bin

# set_bootloader VALUE: openswarm.json with "epuck2": {"bootloader": VALUE}
# (VALUE a JSON value), or without the section for "".
set_bootloader() {
    python3 - "$1" <<'PY'
import json, sys
j = json.load(open("openswarm.json.orig"))
if sys.argv[1]:
    j["epuck2"] = {"bootloader": json.loads(sys.argv[1])}
json.dump(j, open("openswarm.json", "w"), indent=2)
PY
}

# built_at ORIGIN BUDGET BOOTLOADER WHAT: build, and check the images.
built_at() {
    local origin=$1 budget=$2 bootloader=$3 what=$4
    "$openswarm" build | tee build.log
    test -s "$elf" && test -s "$bin"
    local line="Robot image (flash from $origin, $what: openswarm.json's \"epuck2\": {\"bootloader\": \"$bootloader\"}):"
    grep -qxF "$line" build.log || { echo "FAILED: no line '$line' in the build's output"; exit 1; }
    grep -Eq "^Built ./build/epuck2/app-robot.elf and ./build/epuck2/app-robot.bin" build.log
    # Its size, against the flash the setting leaves; the QEMU image's
    # line (the first) against the same.
    grep -A1 "^Robot image" build.log | grep -Eq "^Flash \[.*\] +[0-9.]+% \([1-9][0-9]* of $budget bytes\)$"
    grep -m1 "^Flash" build.log | grep -Eq "^Flash \[.*\] +[0-9.]+% \([1-9][0-9]* of $budget bytes\)$"
    "$openswarm" config show | grep -qxF \
        "robot image build/epuck2/app-robot.elf at $origin, $budget bytes of flash ($what: epuck2.bootloader \"$bootloader\")"
    "$openswarm" build --json > build.json
    python3 - "$elf" "$bin" build.json "$origin" "$budget" "$bootloader" build/epuck2/app.elf <<'PY'
import json, struct, subprocess, sys
elf, binary, result, origin, budget, bootloader, qemu_elf = sys.argv[1:8]
origin, budget = int(origin, 16), int(budget)
j = json.load(open(result))
r = j["robot"]
assert r["image"].endswith("app-robot.elf") and r["bin"].endswith("app-robot.bin"), j
assert r["bootloader"] == bootloader and r["flash_origin"] == origin, j
assert 0 < r["flash"] <= r["flash_total"] == j["flash_total"] == budget, j

def fail(why):
    sys.exit("FAILED: " + elf + " (\"bootloader\": \"" + bootloader + "\"): " + why)

def tool(*argv):
    return subprocess.run(list(argv), capture_output=True, text=True, check=True).stdout

def symbols_of(path):
    symbols = {}
    for line in tool("arm-none-eabi-nm", path).splitlines():
        parts = line.split()
        if len(parts) == 3:
            symbols[parts[2]] = int(parts[0], 16)
    return symbols

def loads_of(path):  # (physical address, bytes in the file) of each loadable segment
    lines = [l.split() for l in tool("arm-none-eabi-readelf", "-lW", path).splitlines() if l.strip().startswith("LOAD")]
    return [(int(l[3], 16), int(l[4], 16)) for l in lines]

def entry_of(path):
    for line in tool("arm-none-eabi-readelf", "-hW", path).splitlines():
        if line.strip().startswith("Entry point address:"):
            return int(line.split(":")[1], 16)
    fail("no entry point in readelf -h")

# Where the image is linked: its first loadable segment and its vector
# table at the origin, its flash within the budget from there.
loads = loads_of(elf)
first_flash = min(address for address, _ in loads)
if first_flash != origin:
    fail("linked at 0x%08x, not 0x%08x" % (first_flash, origin))
symbols = symbols_of(elf)
if symbols.get("stm32f407_vectors") != origin:
    fail("the vector table is at 0x%08x, not 0x%08x" % (symbols.get("stm32f407_vectors", 0), origin))
flash_end = max(address + size for address, size in loads if size and address < 0x20000000)
if flash_end > origin + budget:
    fail("the flash ends at 0x%08x, past the 0x%08x the setting leaves" % (flash_end, origin + budget))
# The .bin: the raw flash from the origin to the image's end.
image = open(binary, "rb").read()
if len(image) != flash_end - origin:
    fail("the .bin is %d bytes, not the %d from 0x%08x to the image's end" % (len(image), flash_end - origin, origin))
sp, reset = struct.unpack_from("<II", image, 0)
if not 0x20000000 < sp <= 0x20020000:
    fail("vector 0 (initial SP) 0x%08x is not in the 128 KB of SRAM" % sp)
if not (reset & 1 and origin <= reset & ~1 < origin + len(image)):
    fail("reset vector 0x%08x is not a Thumb address inside the image (0x%08x + %d bytes)" % (reset, origin, len(image)))
entry = entry_of(elf)
if reset & ~1 != entry & ~1 or reset & ~1 != symbols.get("Reset_Handler"):
    fail("reset vector 0x%08x, ELF entry 0x%08x, Reset_Handler 0x%08x: not one place" % (reset, entry, symbols.get("Reset_Handler", 0)))

# No semihosting: no BKPT 0xAB anywhere in the code.
code = tool("arm-none-eabi-objdump", "-d", elf)
traps = [l for l in code.splitlines() if "bkpt" in l and "0x00ab" in l.replace("0xab", "0x00ab")]
if traps:
    fail("semihosting trap(s) in the robot image:\n" + "\n".join(traps))

# The drivers are in, their handlers in the vector table (weak defaults
# would be left if the drivers were not linked).
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

# QEMU's image: at 0x08000000 whatever the robot's setting.
qemu_first = min(address for address, _ in loads_of(qemu_elf))
if qemu_first != 0x08000000 or symbols_of(qemu_elf).get("stm32f407_vectors") != 0x08000000:
    sys.exit("FAILED: %s is linked at 0x%08x, not QEMU's 0x08000000" % (qemu_elf, qemu_first))
print("robot image (\"%s\"): linked at 0x%08x, entry 0x%08x, SP 0x%08x, %d bytes of %d, no BKPT 0xAB, 9 handlers; "
      "QEMU's at 0x08000000" % (bootloader, origin, entry, sp, len(image), budget))
PY
}

# The default, as the template has it (no "epuck2" section): no bootloader.
built_at 0x08000000 1048576 none "no bootloader"
# The semihosting check does see a trap: QEMU's image has them.
arm-none-eabi-objdump -d build/epuck2/app.elf > qemu.dis
grep -q "bkpt.*0x00ab" qemu.dis
# After the Aseba bootloader, in the same build folder: relinked there.
set_bootloader '"aseba"'
built_at 0x08020000 917504 aseba "after the Aseba bootloader's 128 KB"
# And back, said explicitly.
set_bootloader '"none"'
built_at 0x08000000 1048576 none "no bootloader"

# A bad setting: config check and build refuse it (exit 2) naming the key
# and the choices.
refused() { # DESCRIPTION JSON-VALUE REGEX
    set_bootloader "$2"
    local command status
    for command in "config check" "build"; do
        status=0
        # shellcheck disable=SC2086
        "$openswarm" $command > refused.log 2>&1 || status=$?
        if [ "$status" -ne 2 ] || ! grep -Eq -- "$3" refused.log; then
            echo "FAILED: $command with $1: exit $status (expected 2):"
            cat refused.log
            exit 1
        fi
    done
}
refused "a misspelt choice" '"asbea"' \
    '^openswarm: ./openswarm.json: "epuck2.bootloader": unknown choice "asbea"; expected "none" \(the robot image at 0x08000000.*or "aseba" \(at 0x08020000.* \(did you mean "aseba"\?\)$'
refused "a number" '128' '"epuck2.bootloader": expected .*"none" or "aseba".*found number 128'
python3 -c 'import json; j = json.load(open("openswarm.json.orig")); j["epuck2"] = {"boot": "none"}; json.dump(j, open("openswarm.json", "w"))'
status=0
"$openswarm" config check > refused.log 2>&1 || status=$?
{ [ "$status" -eq 2 ] && grep -q '"epuck2.boot": unknown key; expected one of bootloader' refused.log; } ||
    { echo "FAILED: an unknown key in epuck2: exit $status:"; cat refused.log; exit 1; }
# The section is checked in an app for another port too (as "kilobot"'s
# is), which a build for that port then ignores.
(cd .. && "$openswarm" new kilo --template "$template" --port kilobot > /dev/null)
python3 -c 'import json; j = json.load(open("../kilo/openswarm.json")); j["epuck2"] = {"bootloader": "asbea"}; json.dump(j, open("../kilo/openswarm.json", "w"))'
status=0
"$openswarm" config check -C ../kilo > refused.log 2>&1 || status=$?
{ [ "$status" -eq 2 ] && grep -q '"epuck2.bootloader": unknown choice "asbea"' refused.log; } ||
    { echo "FAILED: a bad epuck2.bootloader in a kilobot app: exit $status:"; cat refused.log; exit 1; }

# The budget is the linker's too: 950 KB of constant data fit the 1 MB of
# "none" and not the 896 KB "aseba" leaves, which the build explains.
cp main.c main.c.orig
sed -i 's|^static uint16_t blinks;$|&\nstatic const unsigned char ballast[950 * 1024] = {1};\nstatic volatile unsigned ballast_at;|;
        s|^    Sys_Init_Kernel();$|&\n    blinks = ballast[ballast_at];|' main.c
grep -q "ballast\[ballast_at\]" main.c || { echo "FAILED: the edit of main.c did not apply"; exit 1; }
set_bootloader '"none"'
"$openswarm" build > big.log 2>&1 || { cat big.log; echo "FAILED: 950 KB did not fit the 1 MB of \"none\""; exit 1; }
grep -A1 "^Robot image" big.log | grep -Eq "^Flash \[=+ *\] +9[0-9.]+% \([0-9]+ of 1048576 bytes\)$" ||
    { cat big.log; echo "FAILED: no 9x% of 1048576 bytes line"; exit 1; }
set_bootloader '"aseba"'
status=0
"$openswarm" build > big.log 2>&1 || status=$?
{ [ "$status" -eq 1 ] && grep -Eq '^openswarm: flash overflow by [0-9]+ bytes: the image does not fit the 917504 bytes the epuck2 leaves a program \(of its 1 MB: openswarm.json.s "epuck2": \{"bootloader": "aseba"\} puts the robot image at 0x08020000, after the Aseba bootloader.s 128 KB\)' big.log; } ||
    { cat big.log; echo "FAILED: 950 KB after the Aseba bootloader: exit $status, not 1 with the explanation"; exit 1; }
cp main.c.orig main.c
cp openswarm.json.orig openswarm.json
echo "1 passed, 0 failed"
