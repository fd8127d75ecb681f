#!/usr/bin/env bash
# End to end, issue 31: `openswarm run --world` on an e-puck2 app runs its
# e-pucks in the world (before, it was refused: "--world: not for the
# epuck2 port, which runs one robot in QEMU"). The app's sources are built
# as --port epuck_world, the host build the world simulator runs.
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
echo "1 passed, 0 failed"
