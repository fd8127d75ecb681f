#!/usr/bin/env bash
# End to end: after `cmake --install`, the installed tool finds the SDK,
# ports, templates and simulator relative to itself, and the main job works.
#   installed.sh BUILD_DIR WORKDIR
set -euo pipefail
build=$1 work=$2
rm -rf "$work" && mkdir -p "$work"
cmake --install "$build" --prefix "$work/prefix" > "$work/install.log"
cd "$work"
env -u OPENSWARM_ROOT "$work/prefix/bin/openswarm" new app --template blinky
"$work/prefix/bin/openswarm" doctor | grep -q "OpenSwarm SDK and templates at $work/prefix/share/openswarm"
"$work/prefix/bin/openswarm" run -C app --time 0.6 2>&1 | tee run.log
grep -q "led    red 0 green 3 blue 0" run.log
"$work/prefix/bin/openswarm" test -C app | grep -q "^1 passed, 0 failed$"
echo "1 passed, 0 failed"
