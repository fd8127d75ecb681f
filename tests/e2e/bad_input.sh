#!/usr/bin/env bash
# End to end: each kind of bad input gets its message and exit status, and
# the file system is left as it was.
#   bad_input.sh OPENSWARM WORKDIR
set -uo pipefail
openswarm=$1 work=$2
rm -rf "$work" && mkdir -p "$work" && cd "$work"
source "$(dirname "$0")/check.sh"


snapshot() { find . -printf '%p %s\n' | sort; }

before=$(snapshot)
expect 2 "unknown template 'blinki'.*did you mean 'blinky'" "$openswarm" new a --template blinki
expect 2 "unknown port 'kilobo'.*did you mean 'kilobot'" "$openswarm" new a --port kilobo
expect 2 "not a usable app name" "$openswarm" new 9lives
expect 2 "openswarm.json: not found.*openswarm new" "$openswarm" build
expect 2 "RequiredError|name is required" "$openswarm" new
expect 2 "unknown command 'biuld' \(did you mean 'build'\?\); commands: new, build, run" "$openswarm" biuld
[ "$before" = "$(snapshot)" ] && passed=$((passed + 1)) || { failed=$((failed + 1)); echo "FAILED: a refused command changed the folder"; }

"$openswarm" new keep >/dev/null
echo "my work" > keep/notes.txt
before=$(snapshot)
expect 2 "keep already exists.*--force" "$openswarm" new keep
[ "$before" = "$(snapshot)" ] && passed=$((passed + 1)) || { failed=$((failed + 1)); echo "FAILED: new overwrote an existing folder"; }

cat > keep/openswarm.json <<'JSON'
{
  "name": "keep",
  "port": "kilobot",,
}
JSON
expect 2 "keep/openswarm.json:3:21: invalid JSON" "$openswarm" build -C keep
err=$("$openswarm" build -C keep 2>&1 >/dev/null)
printf '%s\n' "$err" | grep -q '^      "port": "kilobot",,$' && printf '%s\n' "$err" | grep -q '^                        \^$' \
    && passed=$((passed + 1)) || { failed=$((failed + 1)); echo "FAILED: no caret under the error:"; printf '%s\n' "$err"; }

# A key given twice was last-wins, silently (world.json refuses it).
printf '{\n  "name": "keep",\n  "port": "kilobot",\n  "kernel": {"max_threads": 4, "max_threads": 8}\n}\n' > keep/openswarm.json
expect 2 "keep/openswarm.json:4:32: \"max_threads\" is given twice in this object \(also on line 4\): keep one" "$openswarm" build -C keep
printf '{\n  "name": "keep",\n  "port": "kilobot",\n  "name": "other"\n}\n' > keep/openswarm.json
expect 2 "keep/openswarm.json:4:3: \"name\" is given twice in this object \(also on line 2\): keep one" "$openswarm" config check -C keep
printf '{"name": "keep", "port": "kilobott"}' > keep/openswarm.json
expect 2 "\"port\": unknown port \"kilobott\".*did you mean \"kilobot\"" "$openswarm" build -C keep
# A number beyond a double's range (found by fuzz.app_config: it crashed the tool).
printf '{"name": "keep", "port": "kilobot", "kernel": {"max_threads": 5e555}}' > keep/openswarm.json
expect 2 "keep/openswarm.json: invalid JSON: number overflow parsing '5e555'; write a smaller number" "$openswarm" build -C keep
printf '{"name": "keep"}' > keep/openswarm.json
expect 2 "\"port\": missing" "$openswarm" build -C keep
printf '{"name": 7, "port": "kilobot"}' > keep/openswarm.json
expect 2 "\"name\": expected the app's name, found number 7" "$openswarm" build -C keep
printf '{"name": null, "port": "kilobot"}' > keep/openswarm.json
expect 2 "\"name\": expected the app's name, found null$" "$openswarm" build -C keep
# The same words for an experiment's world (cli/src/experiment_spec.cpp).
printf '{"arena": {"width_mm": null, "height_mm": 1000}}' > experiment.json
expect 2 "experiment.json: \"arena.width_mm\": expected a number 100..100000, found null$" "$openswarm" experiment experiment.json
printf '{"name": "keep", "port": "kilobot", "evnets": []}' > keep/openswarm.json
expect 2 "\"evnets\": unknown key.*did you mean \"events\"" "$openswarm" build -C keep
printf '{"name": "keep", "port": "kilobot", "kernel": {"max_threads": 40}}' > keep/openswarm.json
expect 2 "\"kernel.max_threads\": expected a whole number 2..16, found number 40" "$openswarm" build -C keep
printf '{"name": "keep", "port": "kilobot", "kernel": {"scheduler": "priorty"}}' > keep/openswarm.json
expect 2 "\"kernel.scheduler\": unknown scheduler.*did you mean \"priority\"" "$openswarm" build -C keep
printf '{"name": "keep", "port": "kilobot", "kernel": {"stack_check": 0}}' > keep/openswarm.json
expect 2 "\"kernel.stack_check\": expected true or false, found number 0" "$openswarm" build -C keep
printf '{"name": "keep", "port": "kilobot", "events": [{"name": "hop", "type": "int61"}]}' > keep/openswarm.json
expect 2 "\"events\[0\].type\": unknown type \"int61\".*did you mean \"int16\"" "$openswarm" build -C keep
printf '{"name": "keep", "port": "kilobot", "events": [{"name": "hop", "type": "unit16"}]}' > keep/openswarm.json
expect 2 "\"events\[0\].type\": unknown type \"unit16\".*did you mean \"uint16\"" "$openswarm" build -C keep
# build --json: the failure as JSON on standard output too (it printed nothing there).
check "build --json's failure is JSON on stdout" 0 "unknown type .unit16" python3 -c '
import json, subprocess, sys
r = subprocess.run([sys.argv[1], "build", "--json", "-C", "keep"], capture_output=True, text=True)
j = json.loads(r.stdout)
assert r.returncode == 2 and j["exit_code"] == 2, (r.returncode, j)
print(j["error"][0])' "$openswarm"
printf '{"name": "keep", "port": "kilobot", "events": [{"name": "a"}, {"name": "a"}]}' > keep/openswarm.json
expect 2 "\"events\[1\].name\": \"a\" is declared twice" "$openswarm" build -C keep
printf '{"name": "keep", "port": "kilobot", "kernel": {"max_threads": 2}, "threads": [{"entry": "a"}, {"entry": "b"}]}' > keep/openswarm.json
expect 2 "\"threads\": 2 threads and the system thread need kernel.max_threads >= 3, found 2" "$openswarm" build -C keep
printf '{"name": "keep", "port": "kilobot", "events": [{"name": "blink"}, {"name": "BLINK"}]}' > keep/openswarm.json
expect 2 "\"events\[1\].name\": \"BLINK\" is declared twice \(as \"blink\": both would be EV_BLINK\)" "$openswarm" build -C keep
printf '{"name": "keep", "port": "kilobot", "threads": [{"entry": "a"}, {"entry": "a"}]}' > keep/openswarm.json
expect 2 "\"threads\[1\].entry\": \"a\" starts two threads" "$openswarm" build -C keep
# Pools given too small for what the app and the port register: refused
# (they built, and the app silently did nothing).
printf '{"name": "keep", "port": "kilobot", "events": [{"name": "a"}], "kernel": {"max_events": 10}}' > keep/openswarm.json
expect 2 "\"kernel.max_events\": the kernel's and the kilobot's 10 events and openswarm.json's 1 need 11, found 10" "$openswarm" build -C keep
printf '{"name": "keep", "port": "kilobot", "kernel": {"event_data": 10}}' > keep/openswarm.json
expect 2 "\"kernel.event_data\": .* need 43, found 10" "$openswarm" build -C keep
printf '{"name": "keep", "port": "kilobot", "threads": [{"entry": "a", "stack": 96}], "kernel": {"stack_pool": 50}}' > keep/openswarm.json
expect 2 "\"kernel.stack_pool\": the stacks of 1 thread in openswarm.json, as the pool carves them, need 112, found 50" "$openswarm" build -C keep
printf '{"name": "keep", "port": "kilobot", "threads": [{"entry": "not an identifier"}]}' > keep/openswarm.json
expect 2 "\"threads\[0\].entry\": \"not an identifier\" is not a C identifier" "$openswarm" build -C keep

# A sensor's table: too few points, raw counts out of order, not numbers,
# not a list; refused naming the key, and nothing is generated.
# refused_table POINTS REGEX
refused_table() {
    printf '{"name": "keep", "port": "kilobot", "devices": {"light": {"processor": "table", "points": %s}}}' "$1" \
        > keep/openswarm.json
    local before
    before=$(snapshot)
    expect 2 "$2" "$openswarm" build -C keep
    [ "$before" = "$(snapshot)" ] && passed=$((passed + 1)) || { failed=$((failed + 1)); echo "FAILED: refusing $1 changed the folder"; }
}
refused_table '[[0, 0]]' '"devices.light.points": expected 2..16 \[raw, value\] points, found a list of 1'
refused_table '[[0, 0], [600, 5], [500, 9]]' \
    '"devices.light.points\[2\]\[0\]": expected a raw count above 600 \(raw counts must increase from point to point\), found number 500'
refused_table '[[0, 0], [1023, "max"]]' '"devices.light.points\[1\]\[1\]": expected a whole number -32768..32767, found string "max"'
refused_table '{"0": 0}' '"devices.light.points": expected a list of 2..16 \[raw, value\] points, found object'

# A test whose expectation the app does not meet fails, naming the line.
"$openswarm" new tested >/dev/null
sed -i 's/^0.252,led,0,0,0$/0.252,led,3,0,0/' tested/tests/blinks.trace
out=$("$openswarm" test -C tested 2>&1)
status=$?
if [ "$status" -eq 1 ] && printf '%s' "$out" | grep -q "tests/blinks.trace:4: expected robot 0 led 3 0 0 at 0.252 s, got robot 0 led 0 0 0" \
    && printf '%s' "$out" | grep -q "^0 passed, 1 failed$"; then
    passed=$((passed + 1))
else
    failed=$((failed + 1)); echo "FAILED: a failing app test: exit $status"; printf '%s\n' "$out" | tail -5
fi
# run's own options are checked before the build: nothing is built.
before=$(snapshot)
expect 2 "openswarm: --time abc: give the simulated time in seconds" "$openswarm" run -C tested --time abc
expect 2 "openswarm: --ohc sleep: give MESSAGE@SECONDS" "$openswarm" run -C tested --ohc sleep
expect 2 "openswarm: --clock-spread 9: give a percentage from 0 to 5" "$openswarm" run -C tested --clock-spread 9
[ "$before" = "$(snapshot)" ] && passed=$((passed + 1)) || { failed=$((failed + 1)); echo "FAILED: a refused run changed the folder"; }
# One file per --first: options after -- go to the simulator.
"$openswarm" run -C tested --time 0.2 --first tested/build/kilobot/tested.elf -- --calibration 70,70,65,68 >/dev/null 2>&1 \
    && passed=$((passed + 1)) || { failed=$((failed + 1)); echo "FAILED: --first ELF -- OPTIONS"; }
# Hyphens in app names: the image is my-robot.elf and .hex.
"$openswarm" new my-robot >/dev/null && "$openswarm" build -C my-robot >/dev/null \
    && [ -s my-robot/build/kilobot/my-robot.elf ] && [ -s my-robot/build/kilobot/my-robot.hex ] \
    && passed=$((passed + 1)) || { failed=$((failed + 1)); echo "FAILED: my-robot did not build"; }

# The app's code is built with warnings on; --werror makes them fail the build.
"$openswarm" new warned >/dev/null
sed -i 's/^    blinks++;$/    if (blinks = 3) {}\n    blinks++;/' warned/main.c
out=$("$openswarm" build -C warned 2>&1); status=$?
[ "$status" -eq 0 ] && printf '%s' "$out" | grep -q "main.c:[0-9]*:[0-9]*: warning: suggest parentheses around assignment" \
    && passed=$((passed + 1)) || { failed=$((failed + 1)); echo "FAILED: no warning for if (blinks = 3): exit $status"; }
"$openswarm" build -C warned --werror >/dev/null 2>&1; status=$?
[ "$status" -eq 1 ] && passed=$((passed + 1)) || { failed=$((failed + 1)); echo "FAILED: --werror built a warned app: exit $status"; }

# The smallest pools the checks accept run the app as declared.
"$openswarm" new tight >/dev/null
python3 -c 'import json, sys; j = json.load(open(sys.argv[1])); j["kernel"] = {"max_events": 11, "event_data": 43, "stack_pool": 112}; json.dump(j, open(sys.argv[1], "w"))' tight/openswarm.json
[ "$("$openswarm" run -C tight --time 1 2>&1 | grep -c '\] led ')" -ge 3 ] \
    && passed=$((passed + 1)) || { failed=$((failed + 1)); echo "FAILED: the smallest accepted pools do not run blinky"; }

# run keeps the build's output apart: one line, then the run's own.
rm -rf tight/build
out=$("$openswarm" run -C tight --time 0.3 2>&1)
first=$(printf '%s\n' "$out" | head -1)
if [[ "$first" =~ ^Built\ tight/build/kilobot/tight\.elf\ \(flash\ [0-9]+\ of\ 28672\ bytes ]] \
    && ! printf '%s\n' "$out" | grep -Eq '^(\[[0-9]+/[0-9]+\]|Configuring|-- )'; then
    passed=$((passed + 1))
else
    failed=$((failed + 1)); echo "FAILED: run shows the build's output:"; printf '%s\n' "$out" | head -5
fi

rm -rf empty-app && mkdir empty-app && printf '{"name": "e", "port": "kilobot"}' > empty-app/openswarm.json
expect 2 "no tests: add tests/NAME.trace" "$openswarm" test -C empty-app

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
