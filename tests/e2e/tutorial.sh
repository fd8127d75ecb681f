#!/usr/bin/env bash
# End to end, the tutorial (docs/tutorial.md) as a reader follows it: its
# openswarm.json (step 2), its main.c (step 3) and its test (step 7),
# taken from the page itself, build and pass; and the app answers the
# overhead controller (step 8, issue 31): KiloGUI's Bootload sends the
# robot to its bootloader (before, the tutorial's app, on
# kilobot_devices_init() alone, ran on and could not be reprogrammed).
#   tutorial.sh OPENSWARM TUTORIAL_MD WORKDIR
set -euo pipefail
openswarm=$1 tutorial=$2 work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work"
source "$(dirname "$0")/check.sh"

# The Nth fenced block of kind KIND (```json, ```c, ```) in the tutorial.
block() {
    awk -v kind="$1" -v want="$2" '
        inside && /^```$/ { inside = 0; next }
        inside && n == want { print; next }
        !inside && $0 == "```" kind { n++; inside = 1 }' "$tutorial"
}

"$openswarm" new leader --template blank >/dev/null
cd leader
block json 2 > openswarm.json
block c 1 > main.c
grep -q '"name": "leader"' openswarm.json || fail "no openswarm.json of the tutorial's step 2" openswarm.json
grep -q "robot_devices_init" main.c || fail "the tutorial's main.c does not answer the overhead controller" main.c
# Step 7's test, the lines after "Replace it with": the first plain block
# that starts with "# run:".
awk '/^```/ { if (inside) { if (keep) exit; inside = 0 } else inside = 1; next }
     inside && /^# run:/ { keep = 1 } keep' "$tutorial" > tests/elects.trace
rm tests/stays_quiet.trace
grep -q "^0.293,2,led,0,0,3$" tests/elects.trace || fail "no step 7 test" tests/elects.trace
logged 0 "^1 passed, 0 failed$" "$openswarm" test
# KiloGUI's Bootload at 1 s: the robot jumps to its bootloader, the run
# says so and fails (exit 1), as a robot would wait to be reprogrammed.
logged 1 "^openswarm-sim: (robot 0 )?jumped to the bootloader \(BOOT message\) at 1\.0[0-9]+ s" \
    "$openswarm" run --ohc boot@1 --time 2
# Pause (WAKEUP) holds it, LED dim blue; Run starts it afresh: green again.
logged 0 "led +red 0 green 0 blue 1" "$openswarm" run --ohc wakeup@1 --ohc run@1.5 --time 2
grep -Eq "^\[ +1\.5[0-9]+ s\] led +red 0 green 3 blue 0" out.log || fail "Run did not start the app afresh" out.log
echo "1 passed, 0 failed"
