#!/usr/bin/env bash
# End to end, issue 31: `openswarm run --world` on an e-puck2 app runs its
# e-pucks in the world (before, it was refused: "--world: not for the
# epuck2 port, which runs one robot in QEMU"). The app's sources are built
# as --port epuck_world, the host build the world simulator runs; in the
# native mode the e-pucks' kernels' losses end the run as warnings.
#   epuck2_world.sh OPENSWARM WORKDIR WORLD (a world of e-pucks)
set -euo pipefail
openswarm=$1 work=$2 world=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work"
source "$(dirname "$0")/check.sh"
"$openswarm" new app --port epuck2 >/dev/null
cd app
logged 0 "^--world: the e-puck2 app runs in the world as --port epuck_world" \
    "$openswarm" run --world "$world" --time 1
grep -q "^Open out/arena/viewer.html" out.log || fail "no pointer to the run's outputs" out.log
test -s out/arena/trajectories.csv || fail "no out/arena/trajectories.csv" out.log
test -x build/epuck_world/app || fail "not built for the world: no build/epuck_world/app" out.log
# The e-pucks' kernels warn of what they refused, natively and as
# processes over pipes, as the exact mode does: a subscription made before
# openswarm_app_start() registers the event (fails before: e-puck worlds
# printed no warning; over pipes, still none).
sed -i 's|^    openswarm_app_start();|    Sys_Subscribe_to_Event(EV_BLINK, SYS_PID_SYSTEM, count_blink, NULL); /* not registered yet */\n&|' main.c
refused="^openswarm-sim: \[robots 0-4\] warning: 1 subscription\(s\) refused: the event was not registered.*EPUCK_EVENT_PROXIMITY.*call epuck_devices_init\(\)"
for mode in --native ""; do
    logged 0 "$refused" "$openswarm" run $mode --world "$world" --time 1
    [ "$(grep -c "warning" out.log)" = 1 ] || fail "the e-pucks' warning said more than once ($mode)" out.log
    if grep -q "kilobot" out.log; then fail "a Kilobot's fix for an e-puck ($mode)" out.log; fi
done
logged 1 "warnings? \(above\) and --strict: the run fails" "$openswarm" run --native --world "$world" --time 1 --strict
logged 1 "warnings? \(above\) and --strict: the run fails" "$openswarm" run --world "$world" --time 1 --strict
echo "1 passed, 0 failed"
