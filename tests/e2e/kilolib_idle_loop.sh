#!/usr/bin/env bash
# End to end: "kernel": {"kilolib_idle_loop": true} in openswarm.json
# reaches the firmware: a classic program whose loop() has nothing to do
# sleeps between kilo ticks (the profile shows the CPU asleep most of the
# time), where without it loop() keeps the CPU busy.
#   kilolib_idle_loop.sh OPENSWARM WORKDIR
set -euo pipefail
openswarm=$1 work=$2
rm -rf "$work" && mkdir -p "$work" && cd "$work"
"$openswarm" new idle --template kilolib > /dev/null
cat > idle/main.c <<'C'
#include <kilolib.h>

void setup(void) { set_color(RGB(0, 3, 0)); }
void loop(void) {}

int main(void) {
    kilo_init();
    kilo_start(setup, loop);
    return 0;
}
C
asleep() { # the "(asleep)" share of a 2 s profile, in whole percent
    "$openswarm" run -C idle --time 2 --profile 2>&1 | tee "$1.log" |
        sed -n 's/^ *[0-9]* *\([0-9]*\)\.[0-9]%  (asleep)$/\1/p'
}
busy=$(asleep busy)
python3 - idle/openswarm.json <<'PY'
import json, sys
path = sys.argv[1]
app = json.load(open(path))
app["kernel"] = {"kilolib_idle_loop": True}
json.dump(app, open(path, "w"), indent=2)
PY
idle=$(asleep idle)
grep -rq "#define KILOLIB_IDLE_LOOP 1" idle/build/kilobot/ || { echo "KILOLIB_IDLE_LOOP not in the generated config"; exit 1; }
echo "asleep: ${busy:-0}% classic, ${idle:-0}% with kilolib_idle_loop"
if [ "${busy:-0}" -ge 10 ]; then echo "the classic loop() let the CPU sleep"; cat busy.log; exit 1; fi
if [ "${idle:-0}" -lt 80 ]; then echo "kilolib_idle_loop did not let the CPU sleep"; cat idle.log; exit 1; fi
echo "2 passed, 0 failed"
