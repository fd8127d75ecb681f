#!/usr/bin/env bash
# End to end: when the second build `openswarm build` makes to measure the
# kernel's and the app's shares fails, the build still succeeds and says
# why the shares are missing; `openswarm size`, which needs them, fails.
#   share_unavailable.sh OPENSWARM WORKDIR
set -euo pipefail
openswarm=$1 work=$2
rm -rf "$work" && mkdir -p "$work" && cd "$work"
"$openswarm" new app --template blinky >/dev/null
cd app
# An app (with a CMakeLists.txt of its own) that refuses to configure
# without link-time optimisation, as the attribution build is.
printf 'cmake_minimum_required(VERSION 3.20)\nproject(app C ASM)\nfind_package(OpenSwarm REQUIRED)\nopenswarm_app()\n' > CMakeLists.txt
printf 'if(NOT OPENSWARM_LTO)\n  message(FATAL_ERROR "needs link-time optimisation")\nendif()\n' >> CMakeLists.txt
"$openswarm" build > build.log
cat build.log
test -f build/kilobot/app.elf
grep -q "^Shares of kernel and app: unavailable, configuring the app without link-time optimisation in ./build/kilobot-size failed: CMake Error at CMakeLists.txt" build.log
grep -q "^  needs link-time optimisation$" build.log
grep -q "^Built ./build/kilobot/app.elf for kilobot$" build.log
"$openswarm" build --json > build.json
python3 -c 'import json, sys; j = json.load(open(sys.argv[1])); assert j["share"] is None and "needs link-time optimisation" in j["share_unavailable"] and j["flash"] > 0' build.json
status=0
"$openswarm" size > size.log 2>&1 || status=$?
cat size.log
test "$status" = 1
grep -q "^openswarm: cannot attribute the image's bytes: configuring the app without link-time optimisation" size.log
echo "1 passed, 0 failed"
