#!/usr/bin/env bash
# End to end: openswarm.json's "kilobot": {"overhead_controller": "events"}
# hands the overhead controller's messages to the app as KILOBOT_EVENT_OHC
# (the build writes KILOBOT_OVERHEAD_CONTROL 2 and sizes the event data
# pool for the event's 10 bytes): the app's handler prints KiloGUI's Pause
# (WAKEUP, 133) and keeps blinking, where the port's default holds it; a
# choice that does not exist is refused with the place and a suggestion.
#   ohc_events_json.sh OPENSWARM WORKDIR
set -uo pipefail
openswarm=$1 work=$2
here=$(cd "$(dirname "$0")" && pwd)
source "$here/check.sh"
rm -rf "$work" && mkdir -p "$work" && cd "$work"
"$openswarm" new app --template blinky >/dev/null
cd app
cat > main.c <<'C'
#include <stdio.h>

#include "openswarm/kernel.h"
#include "openswarm/robot.h"
#include "openswarm_app.h"

static bool on_overhead_controller(sys_pid pid, sys_event_id event, const sys_event_data *data) {
    (void)pid;
    (void)event;
    const kilobot_ohc_message *m = data->value;
    printf("overhead controller message %u\n", m->type);
    return true;
}

void blinker(void) {
    for (;;) {
        uint8_t colour = ROBOT_RGB(0, 3, 0);
        Sys_Send_Event(ROBOT_EVENT_LED, &colour, 1);
        Sys_Sleep(250);
        colour = ROBOT_RGB(0, 0, 0);
        Sys_Send_Event(ROBOT_EVENT_LED, &colour, 1);
        Sys_Sleep(250);
    }
}

int main(void) {
    Sys_Init_Kernel();
    sys_status st = robot_devices_init();
    robot_console_init();
    if (st != SYS_OK) printf("robot_devices_init: %s\n", Sys_Status_Name(st));
    openswarm_app_start();
    Sys_Subscribe_to_Event(KILOBOT_EVENT_OHC, SYS_PID_SYSTEM, on_overhead_controller, NULL);
    Sys_Start_Kernel();
    Sys_Run_SystemThread();
    return 0;
}
C
cp openswarm.json openswarm.json.orig
check "by default the port holds the app at Pause" 0 "0\.3[0-9]+ s\] led +red 0 green 0 blue 1" \
    "$openswarm" run --time 0.6 --ohc pause@0.3
sed -i 's/^  "port": "kilobot",$/  "port": "kilobot",\n  "kilobot": { "overhead_controller": "events" },/' openswarm.json
grep -q '"overhead_controller": "events"' openswarm.json || { echo "FAILED: the edit did not apply"; exit 1; }
check "with events the app's handler gets Pause and the app runs on" 0 \
    "overhead controller message 133.\[ +0\.50[0-9]+ s\] led +red 0 green 3 blue 0" \
    "$openswarm" run --time 0.6 --ohc pause@0.3
check "the build says so in the app's configuration" 0 "#define KILOBOT_OVERHEAD_CONTROL 2 /\* \"events\" \*/" \
    cat build/kilobot/openswarm/openswarm_config.h
sed -i 's/"overhead_controller": "events"/"overhead_controller": "event"/' openswarm.json
check "an unknown choice is refused" 2 \
    "\"kilobot.overhead_controller\": unknown choice \"event\".*did you mean \"events\"" \
    "$openswarm" build
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
