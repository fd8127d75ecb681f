#!/usr/bin/env bash
# End to end, issue 31: an app that calls malloc is told "no heap on this
# robot: use static memory" when it builds (exit 1), on the Kilobot (it
# linked avr-libc's malloc, which returned NULL on the robot, stored
# through unchecked) and on the e-puck2 (the linker's "undefined reference
# to `_sbrk'" was all it said). The same app without malloc builds.
#   no_heap.sh OPENSWARM WORKDIR
set -euo pipefail
openswarm=$1 work=$2
rm -rf "$work" && mkdir -p "$work" && cd "$work"
source "$(dirname "$0")/check.sh"
"$openswarm" new app --template blinky >/dev/null
cd app
cp main.c main.c.orig
# A buffer from the heap, written to: the store the robot made through NULL.
sed -i 's|^#include "openswarm_app.h"|&\n#include <stdlib.h>\nuint8_t *volatile buffer;|' main.c
sed -i 's|^    Sys_Init_Kernel();|    buffer = malloc(16);\n    buffer[0] = 1;\n&|' main.c
grep -q "malloc(16)" main.c
heap="^openswarm: no heap on this robot: use static memory \(the app calls malloc, calloc, realloc or free; the PORT's RAM .*a static array or global instead of malloc"
logged 1 "${heap/PORT/kilobot}" "$openswarm" build
if command -v arm-none-eabi-gcc >/dev/null; then
    logged 1 "${heap/PORT/epuck2}" "$openswarm" build --port epuck2
fi
cp main.c.orig main.c
logged 0 "^Built ./build/kilobot/app.elf" "$openswarm" build
echo "1 passed, 0 failed"
