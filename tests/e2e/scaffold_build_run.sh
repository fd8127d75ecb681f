#!/usr/bin/env bash
# End to end: scaffold an app from a template, build it for a port, run it
# in the simulator, and check what the robot did.
#   scaffold_build_run.sh OPENSWARM WORKDIR TEMPLATE PORT SECONDS EXPECTED_REGEX [RUN OPTIONS...]
set -euo pipefail
openswarm=$1 work=$2 template=$3 port=$4 seconds=$5 expected=$6
shift 6
rm -rf "$work" && mkdir -p "$work" && cd "$work"
"$openswarm" new app --template "$template" --port "$port"
test -f app/openswarm.json -a -f app/CMakeLists.txt -a -f app/README.md
grep -q '"name": "app"' app/openswarm.json
cd app
"$openswarm" build | tee build.log
grep -q "^Built ./build/$port/app.elf for $port" build.log
"$openswarm" build --json | tail -1 | grep -q '"flash_total": 32768'
"$openswarm" size | tee size.log
grep -Eq "^Equation \(1\) for this app: RAM = kernel [0-9]+ \+ stacks [0-9]+ \+ event data [0-9]+" size.log
grep -Eq "^  kernel and port +[1-9][0-9]+ +[1-9][0-9]+$" size.log
"$openswarm" run --time "$seconds" "$@" 2>&1 | tee run.log
grep -Eq "$expected" run.log
"$openswarm" test | tee test.log
grep -Eq "^[1-9][0-9]* passed, 0 failed$" test.log
echo "1 passed, 0 failed"
