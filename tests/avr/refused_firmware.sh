#!/usr/bin/env bash
# openswarm-sim refuses firmware it cannot run as a Kilobot's, before
# libsimavr reads it, with exit status 2 and one line saying what is wrong
# and what to do (sim/src/board/elf_check.c, ihex_check.c). Each of the
# ELFs here crashed simavr 1.6 or ran as something it is not.
#   refused_firmware.sh SIMULATOR AVR_GCC FIRMWARE.elf WORKDIR
set -uo pipefail
sim=$(realpath "$1") avr_gcc=$2 firmware=$(realpath "$3") work=$4
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work" && mkdir -p "$work" && cd "$work"
. "$here/../e2e/check.sh"

# An ELF built for another AVR, with the MCU record OpenSwarm's port adds
# (ports/kilobot/src/mcu_tag.c), and without it (a classic Makefile's).
cat > other_mcu.c <<'EOF'
#include <stdint.h>
#define MMCU __attribute__((section(".mmcu"), used))
const struct { uint8_t tag, len; char name[64]; } __attribute__((packed)) mmcu_part MMCU = {1, 64, MCU};
const struct { uint8_t tag, len; uint32_t hz; } __attribute__((packed)) mmcu_clock MMCU = {2, 4, 8000000};
const uint8_t _mmcu[2] MMCU = {0, 0};
int main(void) { for (;;) { } }
EOF
for mcu in attiny85 atmega2560; do
    "$avr_gcc" -mmcu=$mcu -DMCU="\"$mcu\"" -Os -Wl,--undefined=_mmcu,--section-start=.mmcu=0x910000 \
        -o $mcu.elf other_mcu.c || { echo "FAILED: avr-gcc could not build for the $mcu"; exit 1; }
    check "$mcu ELF" 2 "openswarm-sim: $mcu.elf: built for the $mcu, but the Kilobot is an ATmega328P \(build with -mmcu=atmega328p\)" \
        "$sim" --time 0.01 $mcu.elf
done
printf 'int main(void) { for (;;) { } }\n' > plain.c
"$avr_gcc" -mmcu=attiny85 -Os -o plain_attiny85.elf plain.c
check "attiny85 ELF without a record" 2 "plain_attiny85.elf: built for the attiny85, but the Kilobot is an ATmega328P" \
    "$sim" --time 0.01 plain_attiny85.elf
avr-objcopy --remove-section .note.gnu.avr.deviceinfo plain_attiny85.elf bare_attiny85.elf
check "attiny85 ELF without record or note" 2 "bare_attiny85.elf: built for the avr25 core, but the Kilobot's ATmega328P is avr5 \(build with -mmcu=atmega328p\)" \
    "$sim" --time 0.01 bare_attiny85.elf
# The same without a record, for the ATmega328P: still run as a Kilobot's.
"$avr_gcc" -mmcu=atmega328p -Os -o plain_atmega328p.elf plain.c
check "atmega328p ELF without a record" 0 "plain_atmega328p.elf has no MCU record: running it as a Kilobot's ATmega328P at 8 MHz" \
    "$sim" --time 0.01 plain_atmega328p.elf

# Lock bits without fuses (avr-libc's LOCKBITS alone): simavr 1.6 reads the
# lock byte from the .fuse section's data, and crashed without one.
printf '#include <avr/io.h>\n#include <avr/lock.h>\nLOCKBITS = LB_MODE_1;\nint main(void) { for (;;) { } }\n' > lock.c
"$avr_gcc" -mmcu=atmega328p -Os -o lock_only.elf lock.c
check "lock bits without fuses" 2 "lock_only.elf: a .lock section without a .fuse section: simavr 1.6 reads the lock byte from .fuse and crashes \(set the fuses too, with FUSES, or drop LOCKBITS\)" \
    "$sim" --time 0.01 lock_only.elf

# Cut short: said so, not "no MCU record" or ": Success".
head -c 20 "$firmware" > twenty.elf
check "20-byte ELF" 2 "openswarm-sim: twenty.elf: 20 bytes, too short for an ELF file's 52-byte header \(the file is damaged or cut short: build the firmware again\)" \
    "$sim" --time 0.01 twenty.elf
head -c 2000 "$firmware" > truncated.elf
check "truncated ELF" 2 "openswarm-sim: truncated.elf: its section table \([0-9]+ entries at offset [0-9]+\) runs past the end of the file \(2000 bytes\) \(the file is damaged or cut short" \
    "$sim" --time 0.01 truncated.elf
: > empty.elf
check "empty file" 2 "openswarm-sim: empty.elf: not an ELF file" "$sim" --time 0.01 empty.elf
check "a folder" 2 "openswarm-sim: the firmware \. is a folder, not a regular file: give the FIRMWARE.elf" "$sim" --time 0.01 .
# A symbol table whose entry size is 0 (simavr divided by it): its
# sh_entsize field, 36 bytes into its section header.
python3 - "$firmware" <<'EOF'
import struct, sys
elf = bytearray(open(sys.argv[1], "rb").read())
shoff, shnum = struct.unpack_from("<I", elf, 32)[0], struct.unpack_from("<H", elf, 48)[0]
for i in range(shnum):
    if struct.unpack_from("<I", elf, shoff + i * 40 + 4)[0] == 2:  # SHT_SYMTAB
        struct.pack_into("<I", elf, shoff + i * 40 + 36, 0)
open("no_entsize.elf", "wb").write(elf)
EOF
check "symbol table without entry size" 2 "no_entsize.elf: symbol table [0-9]+ has 0-byte entries" \
    "$sim" --time 0.01 no_entsize.elf

# Intel HEX: records are checked before simavr takes them.
avr-objcopy -O ihex -j .text -j .data "$firmware" good.hex
check "a good .hex" 0 "good.hex has no MCU record: running it as a Kilobot's" "$sim" --time 0.01 good.hex
sed '3s/..\(\r\?\)$/00\1/' good.hex > bad_checksum.hex
check ".hex with a bad checksum" 2 "openswarm-sim: bad_checksum.hex: line 3: bad checksum 0x00, expected 0x[0-9A-F]{2} \(the file is damaged" \
    "$sim" --time 0.01 bad_checksum.hex
head -n 5 good.hex > no_end.hex
check ".hex cut short" 2 "no_end.hex: line 6: the end, without the end-of-file record :00000001FF \(the file is cut short" \
    "$sim" --time 0.01 no_end.hex
{ printf ':02000004008179\r\n'; cat good.hex; } > far.hex
check ".hex beyond the flash" 2 "far.hex: line 2: data at 0x810000, outside the ATmega328P's 32 KB flash" \
    "$sim" --time 0.01 far.hex
printf 'hello\n' > text.hex
check "not a .hex" 2 "text.hex: line 1: not an Intel HEX file: its first line should start with ':'" \
    "$sim" --time 0.01 text.hex

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
