#!/usr/bin/env bash
# End to end: scaffold an app from a template, build it for a port, run it
# in the simulator, and check what the robot did.
#   scaffold_build_run.sh OPENSWARM WORKDIR TEMPLATE PORT SECONDS EXPECTED_REGEX [RUN OPTIONS...]
set -euo pipefail
openswarm=$1 work=$2 template=$3 port=$4 seconds=$5 expected=$6
here=$(cd "$(dirname "$0")" && pwd)
shift 6
rm -rf "$work" && mkdir -p "$work" && cd "$work"
"$openswarm" new app --template "$template" --port "$port"
# No CMakeLists.txt: the app's name is written once, in openswarm.json.
test -f app/openswarm.json -a -f app/README.md -a ! -e app/CMakeLists.txt
grep -q '"name": "app"' app/openswarm.json
cd app
"$openswarm" build | tee build.log
grep -q "^Built ./build/$port/app.elf for $port" build.log
grep -Eq "^  kernel and port +[0-9.]+% ~ *[1-9][0-9]* +[0-9.]+% ~ *[1-9][0-9]*$" build.log
# --json: standard output is the JSON alone, progress goes to standard error.
"$openswarm" build --json > build.json
python3 -c 'import json, sys; j = json.load(open(sys.argv[1])); assert j["flash_total"] == 28672 and j["share"]["approximate"]' build.json
"$openswarm" size | tee size.log
grep -Eq "^  kernel and port +[1-9][0-9]+ +[1-9][0-9]+$" size.log
python3 "$here/check_footprint.py" "$here/../.." . size.log build.json
"$openswarm" run --time "$seconds" "$@" 2>&1 | tee run.log
grep -Eq "$expected" run.log
"$openswarm" test | tee test.log
grep -Eq "^[1-9][0-9]* passed, 0 failed$" test.log
echo "1 passed, 0 failed"
