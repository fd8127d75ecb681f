#!/usr/bin/env bash
# End to end: what `openswarm config check` calls valid builds for the
# Kilobot, and what would not fit is refused with the numbers and the fix
# (issue 30: 8 events of 253 bytes and no threads, and a thread entry of
# 20001 characters, were valid and failed to link: RAM overflow by 1112
# bytes, flash by 232).
#   config_fits.sh OPENSWARM WORKDIR
set -uo pipefail
openswarm=$1 work=$2
rm -rf "$work" && mkdir -p "$work" && cd "$work"
source "$(dirname "$0")/check.sh"

"$openswarm" new app >/dev/null || { echo "FAILED: openswarm new app"; exit 1; }
cd app
cat > main.c <<'C'
#include "openswarm/kernel.h"
#include "openswarm/robot.h"
#include "openswarm_app.h"
int main(void) {
    Sys_Init_Kernel();
    robot_devices_init();
    openswarm_app_start();
    Sys_Start_Kernel();
    Sys_Run_SystemThread();
    return 0;
}
C
# events N SIZE: openswarm.json with N events of SIZE bytes and no threads
events() {
    python3 - "$1" "$2" <<'PY'
import json, sys
n, size = int(sys.argv[1]), int(sys.argv[2])
json.dump({"name": "app", "port": "kilobot", "events": [{"name": f"e{k}", "size": size} for k in range(n)]},
          open("openswarm.json", "w"), indent=1)
PY
}

events 8 253
check "8 events of 253 bytes, no threads" 2 \
    "openswarm.json: \"events\[0\].size\": .*the events' data \(2067\).*need about 3267 bytes, more than the kilobot's 2048 of RAM, by 1219; .*make the biggest events' data smaller \(this one's 253 bytes\), or use fewer events; with no threads, \"kernel\": \{\"max_threads\": 1, \"stack_pool\": 0\} frees the stacks' 640 bytes" \
    "$openswarm" config check
events 8 101
check "8 events of 101 bytes: 3 over" 2 "more than the kilobot's 2048 of RAM, by 3;" "$openswarm" config check
# At the edge: valid, and it builds.
events 8 100
check "8 events of 100 bytes: valid" 0 "openswarm.json is valid" "$openswarm" config check
check "8 events of 100 bytes: builds" 0 "Built \./build/kilobot/app.elf for kilobot" "$openswarm" build

# A thread entry (and an event name) is at most 63 characters.
long=$(printf 't%.0s' $(seq 20001))
python3 - "$long" <<'PY'
import json, sys
json.dump({"name": "app", "port": "kilobot", "threads": [{"entry": sys.argv[1], "stack": 96}]},
          open("openswarm.json", "w"), indent=1)
PY
check "a thread entry of 20001 characters" 2 \
    "\"threads\[0\].entry\": \"t{40}...\" is 20001 characters long: a name is 1..63 characters .*; shorten it" \
    "$openswarm" config check
python3 - <<'PY'
import json
json.dump({"name": "app", "port": "kilobot", "events": [{"name": "e" * 64, "type": "none"}]},
          open("openswarm.json", "w"), indent=1)
PY
check "an event name of 64 characters" 2 "\"events\[0\].name\": .* is 64 characters long: a name is 1..63" "$openswarm" config check

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
