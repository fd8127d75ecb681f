#!/usr/bin/env bash
# End to end: one rule for openswarm.json. `config check` refuses, with the
# key and the fix, everything the generated code, config.h, the linker or
# the robot's RAM would refuse (each of these said "valid" and then did not
# build, or built and crashed), and `build` refuses it the same way before
# anything is built; what it calls valid builds and runs. Inputs that
# crashed or hung the tool fail cleanly (exit 2, a short message).
#   config_rule.sh OPENSWARM WORKDIR
set -uo pipefail
openswarm=$1 work=$2
here=$(cd "$(dirname "$0")" && pwd)
source "$here/check.sh"
rm -rf "$work" && mkdir -p "$work" && cd "$work"

"$openswarm" new app >/dev/null
cp app/openswarm.json blinky.json
# with PYTHON: openswarm.json from blinky's, changed by a statement on j.
with() { python3 -c 'import json, sys; j = json.load(open("blinky.json")); exec(sys.argv[1]); json.dump(j, open("app/openswarm.json", "w"))' "$1"; }
# refused DESCRIPTION PYTHON REGEX: config check and build both refuse it
# (exit 2, the message), and build leaves no build folder.
refused() {
    with "$2"
    rm -rf app/build
    check "config check: $1" 2 "$3" "$openswarm" config check -C app
    check "build: $1" 2 "$3" "$openswarm" build -C app
    [ ! -e app/build ] && passed=$((passed + 1)) || { failed=$((failed + 1)); echo "FAILED: build left app/build for $1"; }
}
refused "entry main" "j['threads'].append({'entry': 'main'})" \
    '"threads\[1\].entry": "main" cannot name a thread.s entry function: a function the app already links.*choose another name'
refused "entry Sys_Yield" "j['threads'].append({'entry': 'Sys_Yield'})" '"Sys_Yield" cannot name .*the SDK.s names start with Sys_'
refused "entry int" "j['threads'].append({'entry': 'int'})" '"int" cannot name .*a keyword of C or C\+\+'
refused "entry __x" "j['threads'].append({'entry': '__x'})" '"__x" cannot name .*reserved by C'
refused "entry start_blinker" "j['threads'].append({'entry': 'start_blinker'})" \
    '"threads\[1\].entry": "start_blinker" is the generated code.s name for thread blinker.s start-up'
refused "event class" "j['events'].append({'name': 'class'})" '"events\[1\].name": "class" cannot name an event: a keyword of C or C\+\+'
refused "16 threads" "j['threads'] = [{'entry': 't%d' % i} for i in range(16)]" \
    '"threads": 16 threads and the system thread are more than the kernel.s 16'
refused "250 events" "j['events'] = [{'name': 'e%d' % i} for i in range(250)]" \
    '"events": 250 events and the kilobot.s 10 are more than the kernel.s 255; at most 245 events'
refused "a stack beyond the RAM" "j['threads'][0]['stack'] = 4000" \
    '"threads\[0\].stack": the stacks \(4208 bytes .* more than the kilobot.s 2048 of RAM'
refused "14 threads leaving the main stack no room" \
    "j['threads'] = [{'entry': 't%d' % i, 'stack': 16} for i in range(14)]" 'more than the kilobot.s 2048 of RAM'
refused "stack_pool not in blocks" "j['kernel'] = {'stack_pool': 200}" \
    '"kernel.stack_pool": 200 is not a multiple of the kilobot.s 16-byte stack blocks; give 208'
refused "name all" "j['name'] = 'all'" '"name": "all" cannot name an app: CMake.s own target'
refused "a 40 000-character name" "j['name'] = 'x' * 40000" '"name": "x{40}\.\.\." is not a usable app name'

# Valid means it builds and runs: as many events as the kernel takes, and
# as many threads as the RAM holds with the main stack's minimum.
with "j['events'] += [{'name': 'e%d' % i} for i in range(244)]"
check "245 events: valid" 0 "is valid" "$openswarm" config check -C app
check "245 events: runs" 0 "led +red 0 green 3" "$openswarm" run -C app --time 0.6
with "j['threads'] = [{'entry': 'blinker', 'stack': 16}] + [{'entry': 't%d' % i, 'stack': 16} for i in range(12)]"
for i in $(seq 0 11); do echo "void t$i(void) { for (;;) Sys_Sleep(1000); }"; done >> app/main.c
check "13 threads: valid" 0 "is valid" "$openswarm" config check -C app
check "13 threads: run, the main stack within its room" 0 "main stack: worst use [0-9]+ of [0-9]+ bytes.*ran 1\.000 s" \
    "$openswarm" run -C app --time 1 -- --main-stack

# Inputs that crashed (SIGSEGV, abort) or hung the tool.
cp blinky.json app/openswarm.json
python3 -c 'print("[" * 100000 + "]" * 100000)' > app/openswarm.json
check "JSON nested 100 000 deep" 2 "openswarm.json:1:65: nested more than 64 levels deep" "$openswarm" config check -C app
printf '{"name": "app", "port": "kilobot"}\0{"name": "other"}' > app/openswarm.json
check "a NUL byte" 2 "openswarm.json:1:35: a NUL byte" "$openswarm" config check -C app
python3 -c 'print("{\"name\": \"app\", \"port\": \"kilobot\", \"x\": \"" + "é" * 500000 + "\",}")' > app/openswarm.json
"$openswarm" config check -C app 2> utf8.err
python3 - utf8.err <<'PY' && passed=$((passed + 1)) || { failed=$((failed + 1)); echo "FAILED: a 1 MB line's message:"; head -c 600 utf8.err; }
import sys
data = open(sys.argv[1], "rb").read()
data.decode("utf-8")  # whole characters only
assert len(data) < 400, len(data)
assert b"invalid JSON" in data
PY
with "j['events'] = [{'name': 'e%d' % i} for i in range(200000)]"
SECONDS=0
check "200 000 events, refused in time" 2 '"events": 200000 events' "$openswarm" config check -C app
[ "$SECONDS" -lt 20 ] && passed=$((passed + 1)) || { failed=$((failed + 1)); echo "FAILED: 200 000 events took $SECONDS s"; }
cp blinky.json app/openswarm.json
python3 -c 'print("int long_line = 0;" + " " * 30000 + "#include \"x.h\"")' > app/long_line.c
check "a source line of 30 000 characters" 0 "is valid" "$openswarm" config check -C app
rm app/long_line.c
check "new: a 300-character name" 2 "is not a usable app name.*at most 64 characters" "$openswarm" new "$(printf 'n%.0s' $(seq 300))"
check "new: name all" 2 '"all" cannot name an app' "$openswarm" new all
mkdir -p folder/openswarm.json
check "a folder named openswarm.json" 2 "openswarm.json: a folder, not a file" "$openswarm" config check -C folder
check "new -C a missing folder" 2 "-C missing/dir: no such folder; create it first" "$openswarm" new x -C missing/dir
[ ! -e missing ] && passed=$((passed + 1)) || { failed=$((failed + 1)); echo "FAILED: new -C created the missing folder"; }

# A test file with a time that is no number, or a value with letters after
# it: refused before the build, naming the line (they were read as 0.252
# and 3).
"$openswarm" new tested >/dev/null
sed -i 's/^0.252,led,0,0,0$/nan,led,0,0,0/' tested/tests/blinks.trace
check "test: a nan time" 2 "tests/blinks.trace:4: nan,led,0,0,0: expected time_s,device,a,b,c" "$openswarm" test -C tested
sed -i 's/^nan,led,0,0,0$/0.252,led,3abc,0,0/' tested/tests/blinks.trace
check "test: 3abc" 2 "tests/blinks.trace:4: 0.252,led,3abc,0,0: expected" "$openswarm" test -C tested
[ ! -e tested/build ] && passed=$((passed + 1)) || { failed=$((failed + 1)); echo "FAILED: a refused test built the app"; }

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
