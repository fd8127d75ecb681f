#!/usr/bin/env bash
# End to end: openswarm.json meets the C++ SDK (issue 13). The blinky-cpp
# template declares its thread and a uint16 event; the generated header
# gives the event as openswarm::events::blinked, an Event<uint16_t>, and the
# thread entry C linkage (it failed to link: undefined openswarm_app_start
# and entries). A handler or a wait for another type does not compile
# (Event<uint16_t> on an event declared uint8 compiled and failed at run
# time with -6).
#   cpp_typed_events.sh OPENSWARM WORKDIR
set -uo pipefail
openswarm=$1 work=$2
here=$(cd "$(dirname "$0")" && pwd)
source "$here/check.sh"
rm -rf "$work" && mkdir -p "$work" && cd "$work"

"$openswarm" new app --template blinky-cpp >/dev/null
cp app/main.cpp main.cpp.orig
check "typed events: the test passes" 0 "1 passed, 0 failed" "$openswarm" test -C app
check "the header declares the event's type" 0 "constexpr Event<uint16_t> blinked\{EV_BLINKED\};" \
    cat app/build/kilobot/openswarm/openswarm_app.h

sed -i 's/\[\](const uint16_t &n) { blinks = n; }/[](const uint8_t \&n) { blinks = n; }/' app/main.cpp
grep -q 'const uint8_t &n' app/main.cpp || { echo "FAILED: the edit did not apply"; exit 1; }
check "a handler of another type does not compile" 1 \
    "main.cpp.*the handler must be a lambda taking const T & of the event's data type" \
    "$openswarm" build -C app

cp main.cpp.orig app/main.cpp
sed -i 's|^int main() {|void reader() {\n    uint8_t seen;\n    events::blinked.wait(seen);\n}\n\nint main() {|' app/main.cpp
check "a wait into another type does not compile" 1 "main.cpp:[0-9]+:[0-9]+: error: invalid initialization of (non-const )?reference" \
    "$openswarm" build -C app

# A uint8 event that is sent a uint8_t runs; the same event waited for as
# an Event<uint16_t> made by hand is what failed at run time before.
cp main.cpp.orig app/main.cpp
sed -i 's/"type": "uint16"/"type": "uint8"/' app/openswarm.json
sed -i 's/const uint16_t &n/const uint8_t \&n/; s/events::blinked.send(n)/events::blinked.send((uint8_t)n)/' app/main.cpp
check "the same app with a uint8 event" 0 "1 passed, 0 failed" "$openswarm" test -C app

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
