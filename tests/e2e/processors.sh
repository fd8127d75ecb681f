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
sed -i 's|    robot_devices_init();|    robot_devices_init();\n    openswarm_app_start();|' guarded/main.c
sed -i 's|#include "openswarm/robot.h"|#include "openswarm/robot.h"\n#include "openswarm/kilobot.h"\n#include "openswarm_app.h"|' guarded/main.c
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

# The IR device's distance pre-processor: chosen in openswarm.json, installed
# by the generated code (tests/avr/ir_exchange.c shows what it computes).
printf '{"name": "guarded", "port": "kilobot", "devices": {"ir": {"processor": "distance"}}}' > guarded/openswarm.json
"$openswarm" config show -C guarded | grep -q "device ir: processor distance"
"$openswarm" build -C guarded >/dev/null
grep -q "Sys_Set_Processor(&kilobot_ir, kilobot_ir_with_distance" guarded/build/kilobot/openswarm/openswarm_app.c

bad() { # bad JSON_DEVICES REGEX
    printf '{"name": "guarded", "port": "kilobot", "devices": %s}' "$1" > guarded/openswarm.json
    local err
    if err=$("$openswarm" config check -C guarded 2>&1); then echo "FAILED: accepted $1"; exit 1; fi
    printf '%s' "$err" | grep -Eq "$2" || { echo "FAILED: $1 -> $err"; exit 1; }
}
bad '{"motor": {"processor": "calibrated"}}' '"devices.motor": no device "motor" on kilobot; devices: motors, led, ir, light, voltage, temperature \(did you mean "motors"\?\)'
bad '{"motors": {"processor": "spinup"}}' '"devices.motors.processor": unknown processor "spinup" for motors; processors: calibrated, spinup-limited'
bad '{"motors": {"processor": "spinup-limited", "limit_ms": 50}}' '"devices.motors.fallback": missing'
bad '{"motors": {"processor": "spinup-limited", "limit_ms": 0, "fallback": 1}}' '"devices.motors.limit_ms": expected a whole number 1..60000, found number 0'
bad '{"motors": {"processor": "calibrated", "limit_ms": 5}}' '"devices.motors.limit_ms": unknown key'

# A sensor's table in openswarm.json: the app drives both motors with the
# light it senses, mapped to 0..200 by the table; each trace gives another
# light input (1650 mV = 511 counts -> 118, 300 mV = 93 counts -> 23).
"$openswarm" new sensing --template blank >/dev/null
cat > sensing/openswarm.json <<'JSON'
{
  "name": "sensing",
  "port": "kilobot",
  "devices": { "light": { "processor": "table", "points": [[0, 0], [400, 100], [1023, 200]] } }
}
JSON
cat > sensing/main.c <<'C'
#include "openswarm/kernel.h"
#include "openswarm/kilobot.h"
#include "openswarm_app.h"

static void app_thread(void) {
    Sys_Sleep(10);
    int16_t level = -1;
    kilobot_sense(&kilobot_light, &level);
    kilobot_motors both = {(uint8_t)level, (uint8_t)level};
    Sys_Send_Event(KILOBOT_EVENT_MOTORS, &both, sizeof both);
    for (;;) Sys_Sleep(1000);
}

int main(void) {
    Sys_Init_Kernel();
    kilobot_devices_init();
    kilobot_sensors_init();
    openswarm_app_start();
    Sys_Start_Process(app_thread);
    Sys_Start_Kernel();
    Sys_Run_SystemThread();
    return 0;
}
C
rm sensing/tests/*.trace
printf '# run: --time 0.1 --light 1650\n0.010,motors,118,118,0\n' > sensing/tests/bright.trace
printf '# run: --time 0.1 --light 300\n0.010,motors,23,23,0\n' > sensing/tests/dim.trace
"$openswarm" config show -C sensing | grep -q "device light: processor table, points 0->0 400->100 1023->200"
"$openswarm" test -C sensing | tee sensing.log
grep -q "^2 passed, 0 failed$" sensing.log
grep -q "Sys_Set_Processor(&kilobot_light, kilobot_linear_table, (void \*)&light_params)" \
    sensing/build/kilobot/openswarm/openswarm_app.c
echo "7 passed, 0 failed"
