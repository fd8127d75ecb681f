#!/usr/bin/env bash
# End to end: the kilolib template, with the pools `openswarm build` gives
# it, answers the overhead controller: WAKEUP replaces the program with the
# green status flash (a thread in the slot and stack the program's thread
# leaves), RUN resumes the program's loop() (setup() ran once, at power-up,
# as with the classic library).
#   kilolib_activities.sh OPENSWARM WORKDIR
set -euo pipefail
openswarm=$1 work=$2
rm -rf "$work" && mkdir -p "$work" && cd "$work"
"$openswarm" new app --template kilolib >/dev/null
cd app
"$openswarm" run --time 1.3 --ohc wakeup@0.6 --ohc run@1.0 >run.log 2>&1
after() { # after SECONDS REGEX: a trace line later than SECONDS matches REGEX
    awk -v t="$1" -v re="$2" '/^\[ *[0-9.]+ s\]/ { s = $2; sub(/\[/, "", s); if (s + 0 > t && $0 ~ re) found = 1 }
        END { exit !found }' run.log
}
after 0.6 "led +red 0 green 3 blue 0" || { echo "no green flash after WAKEUP"; cat run.log; exit 1; }
after 1.0 "led +red 0 green 0 blue 3" || { echo "the program did not run again after RUN"; cat run.log; exit 1; }
after 1.0 "motors left 255 right 255" && { echo "setup() ran again after RUN"; cat run.log; exit 1; }
if grep -q "kernel fault" run.log; then echo "a kernel fault"; cat run.log; exit 1; fi
echo "1 passed, 0 failed"
