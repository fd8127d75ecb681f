#!/usr/bin/env bash
# End to end: a device processor chosen in openswarm.json is installed by
# the generated code and acts on the robot; bad choices are refused.
#   processors.sh OPENSWARM WORKDIR
set -euo pipefail
openswarm=$1 work=$2
rm -rf "$work" && mkdir -p "$work" && cd "$work"
"$openswarm" new guarded --template blank >/dev/null
cat > guarded/openswarm.json <<'JSON'
{
  "name": "guarded",
  "port": "kilobot",
  "devices": { "motors": { "processor": "spinup-limited", "limit_ms": 50, "fallback": 100 } }
}
JSON
# The app asks for full power and keeps it; the safety processor does not.
sed -i 's|static void app_thread(void) {|static void app_thread(void) {\n    kilobot_motors full = {255, 255};\n    Sys_Send_Event(KILOBOT_EVENT_MOTORS, \&full, sizeof full);|' guarded/main.c
sed -i 's|    kilobot_devices_init();|    kilobot_devices_init();\n    openswarm_app_start();|' guarded/main.c
sed -i 's|#include "openswarm/kilobot.h"|#include "openswarm/kilobot.h"\n#include "openswarm_app.h"|' guarded/main.c
rm guarded/tests/*.trace
cat > guarded/tests/capped.trace <<'TRACE'
# run: --time 0.3
0.002,motors,255,255,0
0.053,motors,100,100,0
TRACE
"$openswarm" config show -C guarded | grep -q "device motors: processor spinup-limited, fallback 100, limit_ms 50"
"$openswarm" test -C guarded | tee test.log
grep -q "^1 passed, 0 failed$" test.log
grep -q "Sys_Set_Processor(&kilobot_motor_pair, kilobot_spinup_limited" guarded/build/kilobot/openswarm/openswarm_app.c

bad() { # bad JSON_DEVICES REGEX
    printf '{"name": "guarded", "port": "kilobot", "devices": %s}' "$1" > guarded/openswarm.json
    local err
    if err=$("$openswarm" config check -C guarded 2>&1); then echo "FAILED: accepted $1"; exit 1; fi
    printf '%s' "$err" | grep -Eq "$2" || { echo "FAILED: $1 -> $err"; exit 1; }
}
bad '{"motor": {"processor": "calibrated"}}' '"devices.motor": no device "motor" on kilobot; devices: motors, led, ir \(did you mean "motors"\?\)'
bad '{"motors": {"processor": "spinup"}}' '"devices.motors.processor": unknown processor "spinup" for motors; processors: calibrated, spinup-limited'
bad '{"motors": {"processor": "spinup-limited", "limit_ms": 50}}' '"devices.motors.fallback": missing'
bad '{"motors": {"processor": "spinup-limited", "limit_ms": 0, "fallback": 1}}' '"devices.motors.limit_ms": expected a whole number 1..60000, found number 0'
bad '{"motors": {"processor": "calibrated", "limit_ms": 5}}' '"devices.motors.limit_ms": unknown key'
echo "6 passed, 0 failed"
