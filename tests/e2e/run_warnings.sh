#!/usr/bin/env bash
# End to end, issue 31 "no silent failure": what a firmware lost or was
# refused ends `openswarm run` and `openswarm test` with a warning naming
# it and the fix (before, such runs said nothing and exited 0); --strict
# makes the warnings fail them (exit 1), in the exact and the native mode
# (a handler never called too, since the native port notes the handlers
# the kernel calls).
# The apps:
#   - a handler subscribed to KILOBOT_EVENT_LIGHT without
#     kilobot_sensors_init() (the event was never registered);
#   - a kilolib program calling kilobot_sensors_init() (kilolib's pools
#     leave no device slot for the sensors);
#   - a kilolib program printing from an interrupt;
#   - a handler subscribed to an event the app declares and never sends.
#   run_warnings.sh OPENSWARM WORKDIR
set -euo pipefail
openswarm=$1 work=$2
rm -rf "$work" && mkdir -p "$work" && cd "$work"
source "$(dirname "$0")/check.sh"

# A handler on the light sensor's event, which nothing registered.
"$openswarm" new light --template blinky >/dev/null
cd light
sed -i 's|^    Sys_Subscribe_to_Event(EV_BLINK, SYS_PID_SYSTEM, count_blink, NULL);|&\n    Sys_Subscribe_to_Event(KILOBOT_EVENT_LIGHT, SYS_PID_SYSTEM, count_blink, NULL);|' main.c
grep -q KILOBOT_EVENT_LIGHT main.c
refused="^openswarm-sim: warning: 1 subscription\(s\) refused: the event was not registered, the handler never runs .*KILOBOT_EVENT_LIGHT.*; register the event before subscribing to it: call kilobot_sensors_init\(\)"
logged 0 "$refused" "$openswarm" run --time 0.5
logged 1 "^openswarm: the run ended with warnings \(above: each with its fix\), and --strict makes them errors" \
    "$openswarm" run --time 0.5 --strict
grep -Eq "$refused" out.log || fail "no warning of the refused subscription" out.log
logged 0 "^1 passed, 0 failed$" "$openswarm" test
grep -Eq "$refused" out.log || fail "no warning of the refused subscription" out.log
logged 1 "^0 passed, 1 failed$" "$openswarm" test --strict
grep -Eq "$refused" out.log || fail "no warning of the refused subscription" out.log
# The native mode reads the same counters from the host's kernel.
logged 0 "$refused" "$openswarm" run --native --time 0.5
logged 1 "--strict: the run fails" "$openswarm" run --native --time 0.5 --strict
grep -Eq "$refused" out.log || fail "no warning of the refused subscription (native)" out.log
# Three robots refuse the same subscription: one warning naming them all,
# in both modes (before: a copy a robot).
grouped="^openswarm-sim: \[robots 0-2\] warning: 1 subscription\(s\) refused: the event was not registered"
for mode in "" --native; do
    logged 0 "$grouped" "$openswarm" run $mode --time 0.5 --robots 3
    [ "$(grep -c "warning: 1 subscription" out.log)" = 1 ] || fail "the robots' warning said more than once ($mode)" out.log
done
# With the sensors initialised first, nothing to say.
sed -i 's|^    robot_devices_init();|&\n    kilobot_sensors_init();|' main.c
logged 0 "^Running" "$openswarm" run --time 0.5 --strict
if grep -q "warning" out.log; then fail "a warning with the sensors initialised" out.log; fi
cd ..

# An event numbered past the pool (the blinky's 14 events, ids 0-13):
# Sys_Register_Event refuses it uncounted, so its refused subscription is
# the only trace, and the hint names the pool's size to raise.
"$openswarm" new past --template blinky >/dev/null
cd past
sed -i 's|^    Sys_Subscribe_to_Event(EV_BLINK, SYS_PID_SYSTEM, count_blink, NULL);|&\n    Sys_Register_Event(40);\n    Sys_Subscribe_to_Event(40, SYS_PID_SYSTEM, count_blink, NULL);|' main.c
grep -q "Sys_Register_Event(40)" main.c
past="^openswarm-sim: warning: 1 subscription\(s\) refused: the event was not registered.*; an event numbered past the pool .*raise \"max_events\" in openswarm.json's \"kernel\" \(docs/openswarm-json.md\)$"
logged 0 "$past" "$openswarm" run --time 0.5
logged 0 "$past" "$openswarm" run --native --time 0.5
cd ..

# A kilolib program that asks for the analog sensors: kilolib's pools hold
# neither their events' data nor their devices.
"$openswarm" new classic --template kilolib >/dev/null
cd classic
sed -i 's|^    spinup_motors();|    kilobot_sensors_init();\n&|' main.c
sed -i 's|^#include <kilolib.h>|&\n#include <openswarm/kilobot.h>|' main.c
logged 0 "^openswarm-sim: warning: 1 event registration\(s\) refused: no room for the event's data, its handlers never run \(a kilolib program's pool holds kilolib's own: kilobot_sensors_init\(\) needs 6 bytes more\); .*raise \"event_data\"" \
    "$openswarm" run --time 0.5
# Room for their data: then the devices find no slot.
printf '{"name": "classic", "port": "kilobot", "kernel": {"event_data": 64}}' > openswarm.json
logged 0 "^openswarm-sim: warning: 1 device registration\(s\) refused: no free device slot .*kilobot_sensors_init\(\) needs 3 more\); raise \"max_devices\" in openswarm.json's \"kernel\"" \
    "$openswarm" run --time 0.5
printf '{"name": "classic", "port": "kilobot", "kernel": {"event_data": 64, "max_devices": 6}}' > openswarm.json
logged 0 "^Running" "$openswarm" run --time 0.5 --strict
# kilolib's own handlers (its messages, its calls) are not the program's:
# never named, in the native mode either.
logged 0 "^Running" "$openswarm" run --native --time 0.5 --strict
cd ..

# A kilolib program printing once from an interrupt of its own (Timer0's
# compare B, which the port leaves free): its 20 characters ("\r\n" ends
# the line on the debug serial port) cut into loop()'s line.
"$openswarm" new noisy --template kilolib >/dev/null
cd noisy
cat > main.c <<'EOF'
#include <avr/interrupt.h>
#include <kilolib.h>
#include <debug.h>

ISR(TIMER0_COMPB_vect) {
    TIMSK0 &= (uint8_t)~_BV(OCIE0B); /* once */
    printf("from the interrupt\n");
}

void setup(void) {
    TIMSK0 |= _BV(OCIE0B);
}

void loop(void) {
    printf("from loop\n");
    delay(100);
}

int main(void) {
    kilo_init();
    debug_init();
    kilo_start(setup, loop);
    return 0;
}
EOF
logged 0 "^openswarm-sim: warning: 20 character\(s\) printed from an interrupt \(the first at 0\.[0-9]+ s\): they cut into the lines threads print; print from a thread or an event handler" \
    "$openswarm" run --time 0.5
logged 1 "--strict: the run fails" "$openswarm" run --time 0.5 --strict
# A handler subscribed to an event of the app's that nothing sends: it was
# never called, and the run said nothing.
"$openswarm" new quiet --template blinky >/dev/null
cd quiet
sed -i 's|{ "name": "blink", "type": "none" }|&,\n    { "name": "quiet", "type": "none" }|' openswarm.json
sed -i 's|^void blinker(void) {|static bool on_quiet(sys_pid pid, sys_event_id event, const sys_event_data *data) {\n    (void)pid;\n    (void)event;\n    (void)data;\n    blinks += 100;\n    return true;\n}\n\n&|' main.c
sed -i 's|^    Sys_Start_Kernel();|    Sys_Subscribe_to_Event(EV_QUIET, SYS_PID_SYSTEM, on_quiet, NULL);\n&|' main.c
grep -q EV_QUIET main.c
# The event by its name in openswarm_app.h (before: "event 11").
never="^openswarm-sim: warning: the handler on_quiet.*, subscribed to EV_QUIET \(event 11\) on thread 0, was never called in 0\.50[0-9] s: no occurrence of the event reached it .*; send the event, run longer, or unsubscribe"
logged 0 "$never" "$openswarm" run --time 0.5
if grep -q "count_blink" out.log; then fail "count_blink, which ran, named as never called" out.log; fi
logged 1 "--strict: the run fails" "$openswarm" run --time 0.5 --strict
logged 0 "^1 passed, 0 failed$" "$openswarm" test
grep -Eq "^openswarm-sim: warning: the handler on_quiet" out.log || fail "no warning of the handler never called" out.log
# The native mode says the same, named from the shared object (before: nothing).
logged 0 "$never" "$openswarm" run --native --time 0.5
if grep -q "count_blink\|command_handler" out.log; then fail "a handler that ran, or the HAL's, named (native)" out.log; fi
logged 1 "--strict: the run fails" "$openswarm" run --native --time 0.5 --strict
logged 0 "^openswarm-sim: \[robots 0-2\] warning: the handler on_quiet.*, subscribed to EV_QUIET \(event 11\)" \
    "$openswarm" run --native --time 0.5 --robots 3
[ "$(grep -c "the handler on_quiet" out.log)" = 1 ] || fail "the robots' warning said more than once (native)" out.log
# Sent once: called, nothing to say.
sed -i 's|^        Sys_Send_Event(EV_BLINK, NULL, 0);|&\n        Sys_Send_Event(EV_QUIET, NULL, 0);|' main.c
logged 0 "^Running" "$openswarm" run --time 0.5 --strict
if grep -q "warning" out.log; then fail "a warning with the event sent" out.log; fi
logged 0 "^Running" "$openswarm" run --native --time 0.5 --strict
if grep -q "warning" out.log; then fail "a warning with the event sent (native)" out.log; fi
cd ..
echo "1 passed, 0 failed"
