#!/usr/bin/env bash
# End to end: `openswarm upload` of an e-puck2 image through a GDB server
# on a serial port - QEMU's (-gdb pty), standing in for the programmer's
# Black Magic Probe server. QEMU starts with an empty flash and halted; the
# image it then runs to its end, printing the app's records, came through
# the upload. And a port where no GDB server answers fails with that said.
#   upload_epuck2.sh OPENSWARM WORKDIR
set -euo pipefail
openswarm=$1 work=$2
here=$(cd "$(dirname "$0")" && pwd)
source "$here/check.sh"
rm -rf "$work" && mkdir -p "$work" && cd "$work"
"$openswarm" new app --template blinky --port epuck2 >/dev/null
cd app
"$openswarm" build >/dev/null
head -c 8 /dev/zero > empty.bin # stack pointer and reset vector 0: nothing to run

qemu-system-arm -M netduinoplus2 -display none -monitor none -serial file:console.txt \
    -semihosting-config enable=on,target=native,arg=app.elf,arg=--stop-ms=2000 \
    -icount shift=3,align=off,sleep=off -kernel empty.bin -gdb pty -S > qemu.log 2>&1 &
qemu_pid=$!
trap 'kill $qemu_pid 2>/dev/null || true' EXIT
for _ in $(seq 100); do grep -q "/dev/pts/" qemu.log && break; sleep 0.1; done
device=$(grep -o "/dev/pts/[0-9]*" qemu.log) || fail "QEMU did not open its gdb pty" qemu.log
"$openswarm" upload build/epuck2/app.elf --device "$device" > upload.log 2>&1 || fail "upload failed" upload.log qemu.log
grep -q "^Uploading build/epuck2/app.elf through the GDB server on $device" upload.log
grep -q "Section .text, .*: matched." upload.log || fail "compare-sections did not match" upload.log
grep -q "^Uploaded and checked" upload.log
status=0
for _ in $(seq 600); do kill -0 "$qemu_pid" 2>/dev/null || break; sleep 0.1; done
wait "$qemu_pid" || status=$?
[ "$status" -eq 0 ] || fail "the uploaded image did not run to its end (QEMU: $status)" qemu.log console.txt
[ "$(grep -ac $'^\x1eled ' console.txt)" -ge 2 ] || fail "the uploaded blinky did not blink" console.txt
grep -aEq $'^\x1estop 20000[0-9]{2}' console.txt || fail "the uploaded image did not run its 2 s" console.txt

# No GDB server on the port: a terminal nobody answers on.
python3 "$here/fake_ohc.py" silent --mute &
silent_pid=$!
for _ in $(seq 100); do [ -s silent ] && break; sleep 0.1; done
status=0; "$openswarm" upload build/epuck2/app.elf --device "$(cat silent)" > silent.log 2>&1 || status=$?
kill "$silent_pid" 2>/dev/null || true
[ "$status" -eq 1 ] && grep -q "no GDB server answered on /dev/pts/[0-9]* within 5 s: give the programmer's GDB port" silent.log \
    || fail "no GDB server: want exit 1 saying so" silent.log
echo "2 passed, 0 failed"
