#!/usr/bin/env bash
# End to end: an app's parameters (openswarm.json's "parameters"). The
# reporter (metrics/reporter.c) blinks with a half period HALF_PERIOD_MS,
# a parameter (default 250). A sweep over it (sweep/paced.json: 250 and
# 500 ms, 2 s runs) builds the app twice, once per value, and the blinks
# follow the value (4 and 2); run again, it builds nothing and runs
# nothing; in the native mode likewise. `build -D` and `run -D` give one
# value, `test -D` runs the app's tests on the image built with it (a test
# recorded at 250 ms fails at 1000), `size -D` measures that image;
# `config show` lists it; mistakes exit 2.
#   sweep_parameters.sh OPENSWARM WORKDIR
set -euo pipefail
openswarm=$1 work=$2 here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work" && mkdir -p "$work" && cd "$work"
source "$here/check.sh"

"$openswarm" new app --template blinky >/dev/null
sed 's/Sys_Sleep(250)/Sys_Sleep(HALF_PERIOD_MS)/' "$here/metrics/reporter.c" >app/main.c
python3 - app/openswarm.json <<'PY'
import json, sys
config = json.load(open(sys.argv[1]))
config["threads"][0]["stack"] = 256  # printf needs room
config["parameters"] = {"HALF_PERIOD_MS": {"default": 250, "min": 10, "max": 5000,
                                           "doc": "the LED's half period of blinking, in ms"}}
json.dump(config, open(sys.argv[1], "w"), indent=2)
PY
cp "$here/metrics/still.json" world.json
cp "$here/sweep/paced.json" sweep.json

"$openswarm" experiment sweep.json --out a >a.log 2>&1 || fail "the sweep" a.log
grep -q "^Sweeping 2 points x 2 trials = 4 trials of world.json" a.log || fail "the first line" a.log
# Two builds: the default's folder and the other value's.
test "$(grep -c '^Built .*app/build/kilobot\(-p[0-9a-f]\{16\}\)\?/app.elf' a.log)" -eq 2 || fail "two builds" a.log
images=(app/build/kilobot/app.elf app/build/kilobot-p*/app.elf)
test "${#images[@]}" -eq 2 && test -f "${images[1]}" || fail "the second value's build folder" a.log
cmp -s "${images[0]}" "${images[1]}" && fail "the two values built the same image" a.log
grep -qx '1,250,blinks,2,0,4,0,4,4' a/summary.csv || fail "250 ms: 4 blinks in 2 s" a/summary.csv
grep -qx '2,500,blinks,2,0,2,0,2,2' a/summary.csv || fail "500 ms: 2 blinks in 2 s" a/summary.csv
head -1 a/summary.csv | grep -qx 'point,app.HALF_PERIOD_MS,metric,n,failed,mean,sd,ci95_low,ci95_high' \
    || fail "summary.csv's header" a/summary.csv
grep -q '"HALF_PERIOD_MS": 500' a/point-02/trial-01/outcome.json || fail "the outcome's parameters" a/point-02/trial-01/outcome.json
grep -q '"HALF_PERIOD_MS": 250' a/point-01/trial-01/outcome.json || fail "the default's outcome" a/point-01/trial-01/outcome.json

# Again: nothing compiled or linked, nothing simulated.
touch stamp
sleep 1
"$openswarm" experiment sweep.json --out a >again.log 2>&1 || fail "the second run" again.log
grep -q "^4 of 4 trials done (4 by an earlier run), 0 failed" again.log || fail "a resumed run ran again" again.log
rebuilt=$(find app/build -newer stamp \( -name '*.o' -o -name '*.obj' -o -name '*.elf' -o -name '*.a' \) | head -5)
test -z "$rebuilt" || fail "the resumed sweep rebuilt $rebuilt" again.log

# The native mode: its own build per value, the same blinks.
sed 's/\(\[250, 500\]\)/\1, "fidelity": ["native"]/' sweep.json >native.json
"$openswarm" experiment native.json --out n >n.log 2>&1 || fail "the native sweep" n.log
test "$(grep -c '^Built .*app/build/kilobot-native\(-p[0-9a-f]\{16\}\)\?/app.so (native)$' n.log)" -eq 2 \
    || fail "two native builds" n.log
grep -qx '1,250,native,blinks,2,0,4,0,4,4' n/summary.csv && grep -qx '2,500,native,blinks,2,0,2,0,2,2' n/summary.csv \
    || fail "native blinks follow the value" n/summary.csv

"$openswarm" config show -C app >show.log 2>&1 || fail "config show" show.log
grep -qx "parameter HALF_PERIOD_MS 250 (10..5000): the LED's half period of blinking, in ms" show.log \
    || fail "config show's parameter" show.log

# One value for one build or run.
"$openswarm" build -C app -D HALF_PERIOD_MS=500 >build.log 2>&1 || fail "build -D" build.log
grep -q "^Built .*app/build/kilobot-p[0-9a-f]*/app.elf" build.log || fail "build -D's folder" build.log
"$openswarm" run -C app -D HALF_PERIOD_MS=1000 --time 2 >run.log 2>&1 || fail "run -D" run.log
test "$(grep -c 'metric blinks' run.log)" -eq 1 || fail "1000 ms: 1 blink in 2 s" run.log

set +e # check and expect count failures and go on
# test -D and size -D: the tests run, and size measures, the image built with the value.
"$openswarm" test -C app --record blink -- --time 2 >record.log 2>&1 || fail "test --record" record.log
"$openswarm" test -C app blink >test.log 2>&1 || fail "the test at the default" test.log
check "test -D: 1000 ms blinks other than the recorded 250" 1 'blink +FAILED' \
    "$openswarm" test -C app -D HALF_PERIOD_MS=1000 blink
check "test -D: the default's value passes" 0 'blink +PASSED' "$openswarm" test -C app -D HALF_PERIOD_MS=250 blink
"$openswarm" size -C app -D HALF_PERIOD_MS=1000 --time 1 >size.log 2>&1 || fail "size -D" size.log
grep -q "^Image app/build/kilobot-p[0-9a-f]*/app.elf" size.log || fail "size -D's image" size.log
ls -d app/build/kilobot-size-p* >/dev/null 2>&1 || fail "size -D's attribution build in a folder of its own" size.log

# Mistakes: each names the place and the fix (exit 2).
expect 2 '-D HALF_PERIOD_MS=9: parameter HALF_PERIOD_MS takes a whole number 10..5000' \
    "$openswarm" test -C app -D HALF_PERIOD_MS=9
expect 2 '-D HALF_PERIOD_MS=9: parameter HALF_PERIOD_MS takes a whole number 10..5000' \
    "$openswarm" size -C app -D HALF_PERIOD_MS=9
expect 2 '-D HALF_PERIOD_MS=9: parameter HALF_PERIOD_MS takes a whole number 10..5000 .*; give one in its range' \
    "$openswarm" build -C app -D HALF_PERIOD_MS=9
expect 2 'declares no parameter "HALF_PERIOD" .*did you mean "HALF_PERIOD_MS"' "$openswarm" run -C app -D HALF_PERIOD=9
expect 2 '-D "HALF_PERIOD_MS": expected NAME=VALUE' "$openswarm" build -C app -D HALF_PERIOD_MS
sed 's/\[250, 500\]/[250, 6000]/' sweep.json >bad.json
expect 2 'bad.json: "grid.app.HALF_PERIOD_MS": parameter HALF_PERIOD_MS takes a whole number 10..5000' \
    "$openswarm" experiment bad.json --out x
sed 's/app.HALF_PERIOD_MS/app.HALF/' sweep.json >bad.json
expect 2 'bad.json: "grid.app.HALF": .*declares no parameter "HALF"' "$openswarm" experiment bad.json --out x
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
