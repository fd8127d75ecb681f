#!/usr/bin/env bash
# End to end on the e-puck2 under QEMU: scaffold a template for epuck2,
# build it, run it (the status light's changes shown as trace lines), test
# it; options only the Kilobot simulator has, a bad --time and a firmware
# that hangs are refused or fail with the reason.
#   epuck2_qemu.sh OPENSWARM WORKDIR TEMPLATE
set -euo pipefail
openswarm=$1 work=$2 template=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work"
"$openswarm" new app --template "$template" --port epuck2
cd app
"$openswarm" build | tee build.log
grep -q "^Built ./build/epuck2/app.elf for epuck2" build.log
# Against the robot's 1 MB (openswarm.json's default "epuck2": {"bootloader":
# "none"}; e2e.epuck2_robot_image checks "aseba"'s 896 KB).
grep -Eq "^Flash \[.*\] +[0-9.]+% \([1-9][0-9]* of 1048576 bytes\)$" build.log
grep -Eq "^  kernel and port +[0-9.]+% ~ *[1-9][0-9]* " build.log
"$openswarm" build --json > build.json
python3 -c 'import json, sys; j = json.load(open(sys.argv[1])); assert j["flash_total"] == 1048576 and j["ram_total"] == 131072 and j["share"]["approximate"]' build.json
"$openswarm" size | tee size.log
grep -Eq "^Equation \(1\): RAM = C \+ 20 n \+ 8 m \+ sum d_i \+ sum stacks = 220 \+ 20\*[0-9]+ \+ 8\*[0-9]+ \+ [0-9]+ \+ [0-9]+ = [1-9][0-9]* bytes$" size.log
"$openswarm" run --time 1.1 2>&1 | tee run.log
grep -q "^Running app.elf in QEMU (netduinoplus2) for 1.1 s$" run.log
grep -Eq "^\[ +0\.25[0-9]+ s\] led +red 0 green 0 blue 0$" run.log
grep -Eq "^\[ +1\.00[0-9]+ s\] led +red 0 green 3 blue 0$" run.log
test "$(grep -c '\] led ' run.log)" -eq 5
grep -Eq "^openswarm: ran 1.100 s of simulated time in QEMU in [0-9.]+ s" run.log
"$openswarm" test | tee test.log
grep -Eq "^[1-9][0-9]* passed, 0 failed$" test.log

refused() { # EXIT_STATUS REGEX OPTIONS...
    local want=$1 regex=$2 status=0
    shift 2
    "$openswarm" run "$@" > refused.log 2>&1 || status=$?
    test "$status" -eq "$want" || { echo "FAILED: run $* exited $status, not $want"; cat refused.log; exit 1; }
    grep -Eq "$regex" refused.log || { echo "FAILED: run $*:"; cat refused.log; exit 1; }
}
refused 2 "openswarm: --robots, --ohc: not for the epuck2 port, which runs one robot in QEMU" --robots 3 --ohc run@1
refused 2 "openswarm: --time abc: give the simulated time in seconds" --time abc
refused 2 "openswarm: --time nan: give the simulated time in seconds" --time nan

# What the kernel refused ends the run as a warning with an e-puck's fix
# (issue 31: before, runs under QEMU said nothing): a subscription made
# before openswarm_app_start() registers its event. --strict fails the
# run and the test.
cp main.c* ../kept_main
sed -i 's|^int main|static bool too_early(sys_pid pid, sys_event_id event, const sys_event_data *data) {\n    (void)pid;\n    (void)event;\n    (void)data;\n    return true;\n}\n\n&|' main.c*
sed -i 's|^    openswarm_app_start();|    Sys_Subscribe_to_Event(SYS_EVENT_FIRST_FREE, SYS_PID_SYSTEM, too_early, NULL); /* the first event of openswarm.json, not registered yet */\n&|' main.c*
warned="^openswarm: warning: 1 subscription\(s\) refused: the event was not registered, the handler never runs .*EPUCK_EVENT_PROXIMITY.*call epuck_devices_init\(\)"
refused 0 "$warned" --time 0.3
refused 1 "the run ended with warnings \(above: each with its fix\), and --strict makes them errors" --time 0.3 --strict
grep -Eq "$warned" refused.log || { echo "FAILED: no warning with --strict"; cat refused.log; exit 1; }
"$openswarm" test > test.log 2>&1 || { echo "FAILED: test with a warning"; cat test.log; exit 1; }
grep -Eq "$warned" test.log || { echo "FAILED: no warning from test"; cat test.log; exit 1; }
if "$openswarm" test --strict > test.log 2>&1; then echo "FAILED: test --strict passed with a warning"; cat test.log; exit 1; fi
grep -Eq "$warned" test.log || { echo "FAILED: no warning from test --strict"; cat test.log; exit 1; }
cp ../kept_main main.c*
refused 0 "^openswarm: ran 0.300 s" --time 0.3 --strict
if grep -q "warning" refused.log; then echo "FAILED: a warning from the template"; cat refused.log; exit 1; fi

# A firmware that masks every interrupt and spins never reaches its end:
# the run is stopped and fails, saying so.
sed -i 's|    Sys_Start_Kernel();|    __asm__ __volatile__("cpsid i");\n    for (;;) {\n    }\n    Sys_Start_Kernel();|' main.c*
refused 1 "the firmware did not reach 0.1 s of simulated time within [0-9]+ s: it hangs with interrupts masked" --time 0.1
echo "1 passed, 0 failed"
