#!/usr/bin/env bash
# End to end: the pools `openswarm build` generates hold every thread that
# starts, so each one runs:
#  - a classic kilolib program that also declares threads and an event in
#    openswarm.json: the declared threads run beside kilolib's program, which
#    runs on the system thread (no slot or stack of its own);
#  - threads declared without "stack" in an app whose "kernel" sets
#    "default_stack": they get that size, and the pool must hold it.
#   pool_sizing.sh OPENSWARM WORKDIR
set -euo pipefail
openswarm=$1 work=$2
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work" && mkdir -p "$work" && cd "$work"

# built APP: build, then check `openswarm size` against the sources
# (check_footprint.py: the pool and the slots hold every listed thread).
built() {
    (cd "$1" && "$openswarm" build > build.log && "$openswarm" build --json > build.json 2> /dev/null &&
        "$openswarm" size > size.log && python3 "$here/check_footprint.py" "$here/../.." . size.log build.json)
}

# The kilolib template's program (blue blinks), plus: robots exchange their
# ids (kilolib's transmitter), a declared thread beats every 100 ms and
# another prints each beat it waits for.
"$openswarm" new classic --template kilolib > /dev/null
cat > classic/openswarm.json <<'JSON'
{
  "name": "classic",
  "port": "kilobot",
  "events": [ { "name": "beat", "type": "uint8" } ],
  "threads": [ { "entry": "heartbeat" }, { "entry": "echo", "stack": 160 } ]
}
JSON
sed -i 's|#include <kilolib.h>|#include <kilolib.h>\n#include "debug.h"\n#include "openswarm_app.h"\n\nstatic message_t hello;|' classic/main.c
sed -i 's|    kilo_init();|    kilo_init();\n    debug_init();\n    openswarm_app_start();\n    kilo_message_tx = say_hello;\n    kilo_message_rx = heard;|' classic/main.c
sed -i 's|^int main(void) {|static message_t *say_hello(void) { return \&hello; }\n\nstatic void heard(message_t *m, distance_measurement_t *d) {\n    (void)d;\n    printf("heard robot %u\\n", m->data[0]);\n}\n\nint main(void) {|' classic/main.c
sed -i 's|^void setup(void) {|void setup(void) {\n    hello.type = NORMAL;\n    hello.data[0] = (uint8_t)kilo_uid;\n    hello.crc = message_crc(\&hello);|' classic/main.c
cat >> classic/main.c <<'C'

void heartbeat(void) {
    for (uint8_t n = 1;; n++) {
        Sys_Sleep(100);
        Sys_Send_Event(EV_BEAT, &n, 1);
    }
}

void echo(void) {
    for (;;) {
        uint8_t n = 0;
        Sys_Wait_for_Event(EV_BEAT, &n, 1, NULL);
        printf("beat %u\n", n);
    }
}
C
built classic
(cd classic && "$openswarm" run --time 1.1 --robots 2 > run.log 2>&1)
# Robots 0 and 1 (uids 1 and 2): each blinks, hears the other and beats.
for robot in 0 1; do
    grep -Eq "^\[robot $robot\] \[ +0\.5[0-9]+ s\] led +red 0 green 0 blue 0$" classic/run.log
    grep -Eq "^\[robot $robot\] \[ +1\.0[0-9]+ s\] led +red 0 green 0 blue 3$" classic/run.log
    grep -Eq "^\[robot $robot\] heard robot $((2 - robot))$" classic/run.log
    grep -Eq "^\[robot $robot\] beat 10$" classic/run.log
done

# A max_threads that leaves a declared thread no slot is refused (kilolib
# needs none: its program runs on the system thread).
sed -i 's|"port": "kilobot",|"port": "kilobot",\n  "kernel": { "max_threads": 2 },|' classic/openswarm.json
status=0
(cd classic && "$openswarm" build > /dev/null 2> refused.log) || status=$?
[ "$status" -eq 2 ]
grep -q 'openswarm.json: "threads": 2 threads and the system thread need kernel.max_threads >= 3, found 2' classic/refused.log

# Two threads without "stack" and a default of 200 bytes, of which each
# uses 150: the lights turn green and the motors run.
"$openswarm" new roomy --template blank > /dev/null
cat > roomy/openswarm.json <<'JSON'
{
  "name": "roomy",
  "port": "kilobot",
  "kernel": { "default_stack": 200 },
  "threads": [ { "entry": "lights" }, { "entry": "wheels" } ]
}
JSON
cat > roomy/main.c <<'C'
#include <string.h>

#include "openswarm/kernel.h"
#include "openswarm/kilobot.h"
#include "openswarm_app.h"

/* value, passed through a 150-byte buffer on the thread's stack. */
static uint8_t through_stack(uint8_t value) {
    volatile uint8_t scratch[150];
    memset((void *)scratch, value, sizeof scratch);
    Sys_Sleep(10);
    return scratch[sizeof scratch - 1];
}

void lights(void) {
    uint8_t green = through_stack(KILOBOT_RGB(0, 3, 0));
    Sys_Send_Event(KILOBOT_EVENT_LED, &green, 1);
    for (;;) Sys_Sleep(1000);
}

void wheels(void) {
    uint8_t duty = through_stack(200);
    kilobot_motors both = {duty, duty};
    Sys_Send_Event(KILOBOT_EVENT_MOTORS, &both, sizeof both);
    for (;;) Sys_Sleep(1000);
}

int main(void) {
    Sys_Init_Kernel();
    kilobot_devices_init();
    openswarm_app_start();
    Sys_Start_Kernel();
    Sys_Run_SystemThread();
    return 0;
}
C
built roomy
(cd roomy && "$openswarm" run --time 0.1 > run.log 2>&1)
grep -Eq "led +red 0 green 3 blue 0" roomy/run.log
grep -Eq "motors left 200 right 200" roomy/run.log

# The same app without the kernel's optional features: the generated
# configuration turns them off, the stacks carry no guard, the image is
# smaller by hundreds of bytes, and it runs the same (with the periodic
# tick: no tickless idle).
cp -r roomy lean
sed -i 's|"kernel": { "default_stack": 200 }|"kernel": { "default_stack": 200, "stack_check": false, "clock_event": false, "tickless": false }|' lean/openswarm.json
rm -rf lean/build
built lean
grep -q "^#define OS_CFG_STACK_CHECK 0$" lean/build/kilobot/openswarm/openswarm_config.h
grep -q "^#define OS_CFG_CLOCK_EVENT 0$" lean/build/kilobot/openswarm/openswarm_config.h
grep -q "^#define OS_CFG_TICKLESS 0$" lean/build/kilobot/openswarm/openswarm_config.h
"$openswarm" config show -C lean | grep -q "^kernel.stack_check false$"
"$openswarm" config show -C lean | grep -q "^kernel.clock_event false$"
"$openswarm" config show -C lean | grep -q "^kernel.tickless false$"
flash() { python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["flash"])' "$1/build.json"; }
[ $(( $(flash roomy) - $(flash lean) )) -gt 300 ] || { echo "lean saves $(( $(flash roomy) - $(flash lean) )) B"; exit 1; }
(cd lean && "$openswarm" run --time 0.1 > run.log 2>&1)
grep -Eq "led +red 0 green 3 blue 0" lean/run.log
grep -Eq "motors left 200 right 200" lean/run.log
echo "4 passed, 0 failed"
