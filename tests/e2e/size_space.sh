#!/usr/bin/env bash
# End to end: `openswarm size` of an app whose path holds a space (its
# link map's path went to the linker unquoted: -Wl,-Map=/my apps/...).
#   size_space.sh OPENSWARM WORKDIR
set -uo pipefail
openswarm=$1 work=$2
rm -rf "$work" && mkdir -p "$work/my apps" && cd "$work/my apps"
"$openswarm" new blinky --template blinky --port kilobot > /dev/null || { echo "FAILED: new"; exit 1; }
"$openswarm" size -C blinky > size.log 2>&1
status=$?
cat size.log
[ "$status" -eq 0 ] || { echo "FAILED: openswarm size exited $status"; exit 1; }
grep -Eq "^  kernel and port +[1-9][0-9]+ +[1-9][0-9]+$" size.log || { echo "FAILED: no attribution"; exit 1; }
test -f "blinky/build/kilobot-size/link.map" || { echo "FAILED: no link map in the app's folder"; exit 1; }
echo "1 passed, 0 failed"
