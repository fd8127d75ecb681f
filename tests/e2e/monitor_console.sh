#!/usr/bin/env bash
# End to end: `openswarm monitor` on a pseudo-terminal fed by the
# simulator's console (pty_console.py): what the robot printed comes out
# byte for byte, at the robot's baud rate (or --baud's), until Ctrl-C
# (exit 0); a missing port, a port in use and a rate no port takes are
# refused (exit 2). Completion knows both commands.
#   monitor_console.sh OPENSWARM SIMULATOR WORKDIR
set -euo pipefail
openswarm=$1 simulator=$2 work=$3
here=$(cd "$(dirname "$0")" && pwd)
source "$here/check.sh"
rm -rf "$work" && mkdir -p "$work" && cd "$work"
"$openswarm" new app --template threads-and-events >/dev/null
cd app
"$openswarm" build >/dev/null
"$simulator" --time 3 build/kilobot/app.elf > console.txt 2> simulator.log
[ "$(grep -c . console.txt)" -ge 3 ] || fail "the simulated robot printed too little to test with" console.txt

python3 "$here/pty_console.py" port start < console.txt &
feeder_pid=$!
trap 'kill $feeder_pid 2>/dev/null || true' EXIT
for _ in $(seq 100); do [ -s port ] && break; sleep 0.1; done
"$openswarm" monitor --device "$(cat port)" > shown.txt 2> monitor.log &
monitor_pid=$!
for _ in $(seq 100); do grep -q "monitoring" monitor.log && break; sleep 0.1; done
grep -q "^openswarm: monitoring /dev/pts/[0-9]* at 38400 baud; Ctrl-C to quit$" monitor.log \
    || fail "the monitor did not say the port and the Kilobot's rate" monitor.log
touch start
for _ in $(seq 200); do cmp -s console.txt shown.txt && break; sleep 0.1; done

# The port in use while the first monitor holds it; a rate no port takes.
status=0; "$openswarm" monitor --device "$(cat port)" > busy.log 2>&1 || status=$?
[ "$status" -eq 2 ] && grep -q "is in use by another program" busy.log || fail "a port in use: want exit 2" busy.log

kill -INT "$monitor_pid"
status=0; wait "$monitor_pid" || status=$?
cmp console.txt shown.txt || fail "the monitor did not show the console byte for byte" console.txt shown.txt
[ "$status" -eq 0 ] && grep -q "monitor stopped" monitor.log || fail "Ctrl-C: want exit 0 (got $status)" monitor.log

status=0; "$openswarm" monitor --device "$(cat port)" --baud 12345 > baud.log 2>&1 || status=$?
[ "$status" -eq 2 ] && grep -q "baud 12345: not a rate serial ports take here; give one of 9600" baud.log \
    || fail "--baud 12345: want exit 2" baud.log
"$openswarm" monitor --device "$(cat port)" --port epuck2 > /dev/null 2> epuck.log &
pid=$!
for _ in $(seq 100); do grep -q "monitoring" epuck.log && break; sleep 0.1; done
kill -INT "$pid"; wait "$pid"
grep -q "at 115200 baud" epuck.log || fail "the e-puck2's rate is 115200" epuck.log
"$openswarm" monitor --device "$(cat port)" --baud 9600 > /dev/null 2> b9600.log &
pid=$!
for _ in $(seq 100); do grep -q "monitoring" b9600.log && break; sleep 0.1; done
kill -INT "$pid"; wait "$pid"
grep -q "at 9600 baud" b9600.log || fail "--baud 9600 is not used" b9600.log

status=0; "$openswarm" monitor --device /dev/ttyUSB97 > missing.log 2>&1 || status=$?
[ "$status" -eq 2 ] && grep -q "/dev/ttyUSB97: no such serial port" missing.log || fail "a missing port: want exit 2" missing.log
# Shell completion offers the new commands and their options (made from CLI11's tree).
"$openswarm" completion bash > completion.bash
grep -q "upload monitor" completion.bash && grep -q -- "--baud" completion.bash && grep -q -- "--rounds" completion.bash \
    || fail "completion lacks upload or monitor" completion.bash
echo "7 passed, 0 failed"
