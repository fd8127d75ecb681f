#!/usr/bin/env bash
# End to end: a parameter the firmware reads from the EEPROM ("at":
# "eeprom" in openswarm.json). The reporter (metrics/reporter.c) blinks
# with a half period HALF_PERIOD_MS and reports it at start (metric
# half_period_ms). A sweep over it (sweep/eeprom.json: 250 and 500 ms,
# 2 s runs) builds the app once for both points - the world's "eeprom"
# bytes set the value per run - and the robots read each point's value
# (4 and 2 blinks); in the native mode likewise. A run without the bytes
# reads the default; bad values and bytes are refused with the place.
#   sweep_eeprom.sh OPENSWARM OPENSWARM-SIM WORKDIR
set -euo pipefail
openswarm=$1 sim=$2 work=$3 here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work" && mkdir -p "$work" && cd "$work"
source "$here/check.sh"

"$openswarm" new app --template blinky >/dev/null
sed -e 's/Sys_Sleep(250)/Sys_Sleep(HALF_PERIOD_MS)/' \
    -e 's/^    unsigned blinks = 0;/&\n    printf("metric half_period_ms %ld\\n", (long)HALF_PERIOD_MS);/' \
    "$here/metrics/reporter.c" >app/main.c
python3 - app/openswarm.json <<'PY'
import json, sys
config = json.load(open(sys.argv[1]))
config["threads"][0]["stack"] = 256  # printf needs room
config["parameters"] = {"HALF_PERIOD_MS": {"default": 250, "min": 10, "max": 5000, "at": "eeprom",
                                           "doc": "the LED's half period of blinking, in ms"}}
json.dump(config, open(sys.argv[1], "w"), indent=2)
PY
cp "$here/metrics/still.json" world.json
cp "$here/sweep/eeprom.json" sweep.json

"$openswarm" experiment sweep.json --out a >a.log 2>&1 || fail "the sweep" a.log
# One build for the two points: the values are in the EEPROM, not the image.
test "$(grep -c '^Built ' a.log)" -eq 1 || fail "one build for two values" a.log
grep -q '^Built .*app/build/kilobot/app.elf' a.log || fail "the defaults' folder" a.log
ls -d app/build/kilobot-p* >/dev/null 2>&1 && fail "a build folder for a value" a.log
grep -qx '1,250,half_period_ms,1,0,250,0,250,250' a/summary.csv || fail "250 read from the EEPROM" a/summary.csv
grep -qx '2,500,half_period_ms,1,0,500,0,500,500' a/summary.csv || fail "500 read from the EEPROM" a/summary.csv
grep -qx '1,250,blinks,1,0,4,0,4,4' a/summary.csv || fail "250 ms: 4 blinks in 2 s" a/summary.csv
grep -qx '2,500,blinks,1,0,2,0,2,2' a/summary.csv || fail "500 ms: 2 blinks in 2 s" a/summary.csv
python3 - a/point-02/trial-01/world.json <<'PY' || fail "the point's world holds the value's bytes" a/point-02/trial-01/world.json
import json, sys
# 500 - min 10 = 490 = 0x1EA, little-endian, at the app's first address.
assert json.load(open(sys.argv[1]))["eeprom"] == [{"address": 256, "bytes": [234, 1, 0, 0]}]
PY

# The native mode: one build, the same values.
sed 's/\(\[250, 500\]\)/\1, "fidelity": ["native"]/' sweep.json >native.json
"$openswarm" experiment native.json --out n >n.log 2>&1 || fail "the native sweep" n.log
test "$(grep -c '^Built .*app.so (native)$' n.log)" -eq 1 || fail "one native build" n.log
grep -qx '1,250,native,half_period_ms,1,0,250,0,250,250' n/summary.csv &&
    grep -qx '2,500,native,half_period_ms,1,0,500,0,500,500' n/summary.csv &&
    grep -qx '2,500,native,blinks,1,0,2,0,2,2' n/summary.csv || fail "native values read from the EEPROM" n/summary.csv

"$openswarm" config show -C app >show.log 2>&1 || fail "config show" show.log
grep -qx "parameter HALF_PERIOD_MS 250 (10..5000) at EEPROM 0x100: the LED's half period of blinking, in ms" show.log \
    || fail "config show's parameter" show.log

# No bytes in the world: the EEPROM is erased there, the default holds.
"$openswarm" run -C app --world "$work/world.json" --time 1 >run.log 2>&1 || fail "run in the world" run.log
test "$(grep -c 'metric half_period_ms 250' run.log)" -eq 3 || fail "the default without bytes" run.log

set +e # expect counts failures and goes on
sed 's/\[250, 500\]/[250, 6000]/' sweep.json >bad.json
expect 2 'bad.json: "grid.app.HALF_PERIOD_MS": parameter HALF_PERIOD_MS takes a whole number 10..5000' \
    "$openswarm" experiment bad.json --out x
bytes() { python3 -c "import json,sys; w=json.load(open('world.json')); w['eeprom']=json.loads(sys.argv[1]); print(json.dumps(w))" "$1" >"$2"; }
bytes '[{"address": 16, "bytes": [1]}]' low.json
expect 2 'low.json:.*eeprom\[0\].address.*256..1023 \(kilolib keeps its calibration and uid below 256\)' \
    "$sim" --world low.json app/build/kilobot/app.elf
bytes '[{"address": 1022, "bytes": [1, 2, 3, 4]}]' end.json
expect 2 'end.json:.*no room: 4 bytes from 0x3FE pass the EEPROM.s end \(0x3FF\); start them lower' \
    "$sim" --world end.json app/build/kilobot/app.elf
bytes '[{"address": 256, "bytes": [1, 2]}, {"address": 257, "bytes": [3]}]' twice.json
expect 2 'twice.json:.*the byte at 0x101 is given twice' "$sim" --world twice.json app/build/kilobot/app.elf
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
