#!/usr/bin/env bash
# End to end: `openswarm upload` of a Kilobot app through a stand-in
# overhead controller on a pseudo-terminal (fake_ohc.py), which checks
# Bootload, the page count and every page byte for byte against the .hex;
# and upload's errors: no such port, not a serial port, a port in use, a
# port nobody reads (timeout), a .hex too large, a damaged .hex.
#   upload_kilobot.sh OPENSWARM WORKDIR
set -euo pipefail
openswarm=$1 work=$2
here=$(cd "$(dirname "$0")" && pwd)
source "$here/check.sh"
rm -rf "$work" && mkdir -p "$work" && cd "$work"
"$openswarm" new app --template blinky >/dev/null
cd app
"$openswarm" build >/dev/null
hex=build/kilobot/app.hex

# Start the fake controller; its terminal's name in $1 once it is there.
start_fake() {
    rm -f "$1"
    python3 "$here/fake_ohc.py" "$@" > "$1.log" 2>&1 &
    fake_pid=$!
    for _ in $(seq 100); do [ -s "$1" ] && return; sleep 0.1; done
    fail "the fake overhead controller did not start" "$1.log"
}

# 1. KiloGUI's timing (0.13 s a page), one round; then two rounds, faster.
start_fake port1 "$hex" 1
"$openswarm" upload --device "$(cat port1)" > up1.log 2>&1 || fail "upload failed" up1.log
wait "$fake_pid" || fail "the fake controller found a wrong packet" port1.log up1.log
grep -q "every byte as in the .hex" port1.log || fail "the fake controller did not check the pages" port1.log
grep -Eq "^Uploading \./build/kilobot/app.hex \([0-9]+ bytes, [0-9]+ pages of 128\) through the overhead controller on /dev/pts/" up1.log \
    && grep -q "^  round 1: [0-9]* pages sent" up1.log || fail "upload did not say what it sent" up1.log
start_fake port2 "$hex" 2
"$openswarm" upload --device "$(cat port2)" --rounds 2 --page-gap 0.01 > up2.log 2>&1 || fail "upload --rounds 2 failed" up2.log
wait "$fake_pid" || fail "the fake controller found a wrong packet (2 rounds)" port2.log up2.log
grep -q "^fake OHC: 2 rounds" port2.log || fail "the fake controller did not see 2 rounds" port2.log

# 2. No such port; not a serial port (a character device that is no tty, a file).
status=0; "$openswarm" upload --device /dev/ttyUSB97 > e1.log 2>&1 || status=$?
[ "$status" -eq 2 ] && grep -q "/dev/ttyUSB97: no such serial port (.*); is the cable plugged in? give the robot's serial port with --device" e1.log \
    || fail "a missing port: want exit 2 naming it" e1.log
status=0; "$openswarm" upload --device /dev/null > e2.log 2>&1 || status=$?
[ "$status" -eq 2 ] && grep -q "/dev/null is not a serial port" e2.log || fail "/dev/null: want exit 2, not a serial port" e2.log
status=0; "$openswarm" upload --device openswarm.json > e3.log 2>&1 || status=$?
[ "$status" -eq 2 ] && grep -q "openswarm.json is not a serial port (not a character device)" e3.log \
    || fail "a file as the port: want exit 2" e3.log

# 3. A port in use (a monitor holds it).
start_fake port3 --mute
"$openswarm" monitor --device "$(cat port3)" > held.log 2>&1 &
monitor_pid=$!
for _ in $(seq 100); do grep -q "monitoring" held.log && break; sleep 0.1; done
status=0; "$openswarm" upload --device "$(cat port3)" > e4.log 2>&1 || status=$?
kill -INT "$monitor_pid"; wait "$monitor_pid" || true
[ "$status" -eq 2 ] && grep -q "is in use by another program (a monitor, KiloGUI?): close it and retry" e4.log \
    || fail "a port in use: want exit 2" e4.log

# 4. Nobody reads the port: 20 KB of pages fill the terminal's buffer.
python3 - > big.hex <<'PY'
import random
random.seed(1)
for address in range(0, 20480, 16):
    data = bytes(random.randrange(256) for _ in range(16))
    raw = bytes([16, address >> 8, address & 255, 0]) + data
    print(":" + raw.hex().upper() + "%02X" % (-sum(raw) & 255))
print(":00000001FF")
PY
status=0; "$openswarm" upload big.hex --device "$(cat port3)" --page-gap 0 --timeout 1 > e5.log 2>&1 || status=$?
kill "$fake_pid" 2>/dev/null || true
[ "$status" -eq 1 ] && grep -q "took no bytes for 1 s: nothing at the other end reads them; check that it is the right port" e5.log \
    || fail "a port nobody reads: want exit 1 after the timeout" e5.log

# 5. Too large (221 pages) and damaged, refused before any port is opened.
python3 - > huge.hex <<'PY'
for address in range(0, 221 * 128, 16):
    raw = bytes([16, (address >> 8) & 255, address & 255, 0]) + bytes(16)
    print(":" + raw.hex().upper() + "%02X" % (-sum(raw) & 255))
print(":00000001FF")
PY
status=0; "$openswarm" upload huge.hex --device /dev/ttyUSB97 > e6.log 2>&1 || status=$?
[ "$status" -eq 2 ] && grep -q "huge.hex fills 28288 bytes of flash, 221 pages; the overhead controller sends at most 220 pages of 128 bytes (28160 bytes): make the app smaller" e6.log \
    || fail "a .hex too large: want exit 2" e6.log
python3 -c '
import sys
lines = open(sys.argv[1]).read().split("\n")
line = lines[2].rstrip("\r")
lines[2] = line[:-2] + ("01" if line[-2:] == "00" else "00")
print("\n".join(lines), end="")' "$hex" > damaged.hex
status=0; "$openswarm" upload damaged.hex --device /dev/ttyUSB97 > e7.log 2>&1 || status=$?
[ "$status" -eq 2 ] && grep -q "damaged.hex:3: wrong checksum (the file is damaged); rebuild it" e7.log \
    || fail "a damaged .hex: want exit 2 naming the line" e7.log
echo "7 passed, 0 failed"
