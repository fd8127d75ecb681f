#!/usr/bin/env bash
# End to end: the native mode through the tool. The disperse template built
# for the host (`openswarm build --native`) and run in its packed world
# (`openswarm run --native`): the robots spread out and the picture and the
# viewer are written; a world with "fidelity": "native" is run natively
# without being asked; and the mistakes are refused with their fix.
#   native_run.sh OPENSWARM OPENSWARM_SIM WORKDIR
set -uo pipefail
openswarm=$1 sim=$2 work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
source "$(dirname "$0")/check.sh"
"$openswarm" new app --template disperse >/dev/null || exit 1

check "build --native" 0 "Built app/build/kilobot-native/app.so for kilobot, native" \
    "$openswarm" build -C app --native
test -s app/build/kilobot-native/app.so || { echo "no app.so"; failed=$((failed + 1)); }
check "run --native in the packed world" 0 "Built .*app.so \(native\).*ran 120.000 s of simulated time \(10 robots\).*Open app/out/packed/viewer.html" \
    "$openswarm" run -C app --native --world app/worlds/packed.json
python3 "$(dirname "$0")/spread.py" app/out/packed/trajectories.csv 10 120 && passed=$((passed + 1)) || failed=$((failed + 1))
for f in final.png viewer.html; do
    test -s "app/out/packed/$f" && passed=$((passed + 1)) || { echo "FAILED: no $f"; failed=$((failed + 1)); }
done

# A world that asks for the native mode gets it from plain `run`.
sed 's/"seed": 7,/"seed": 7, "fidelity": "native",/' app/worlds/packed.json >native.json
check "\"fidelity\": \"native\" builds and runs natively" 0 "Built .*app.so \(native\).*ran 5.000 s" \
    "$openswarm" run -C app --world native.json --time 5

# The template's thousand robots (10 minutes natively; 3 s here), with
# their picture and viewer.
check "the thousand-robot world" 0 "Built .*app.so \(native\).*ran 3.000 s of simulated time \(1000 robots\).*Open app/out/thousand/viewer.html" \
    "$openswarm" run -C app --world app/worlds/thousand.json --time 3
for f in final.png viewer.html; do
    test -s "app/out/thousand/$f" && passed=$((passed + 1)) || { echo "FAILED: no thousand/$f"; failed=$((failed + 1)); }
done

# Two apps in one world: the packed disperse robots run the app (their
# group names no firmware), two more a blinker's .so named by their group;
# the overhead controller pauses them all at 2 s. The blinkers show blue,
# never the disperse robots' red or green, until the pause darkens them.
"$openswarm" new blinker --template kilolib >/dev/null || exit 1
check "build the blinker --native" 0 "Built blinker/build/kilobot-native/blinker.so" \
    "$openswarm" build -C blinker --native
python3 - "$work" <<'PY' || exit 1
import json, sys
world = json.load(open("app/worlds/packed.json"))
world["robots"].append({"firmware": sys.argv[1] + "/blinker/build/kilobot-native/blinker.so",
                        "poses": [{"x_mm": 30, "y_mm": 30}, {"x_mm": 80, "y_mm": 30}]})
json.dump(world, open("two_apps.json", "w"))
PY
check "run --native --ohc in a world of two apps" 0 "ran 4.000 s of simulated time \(12 robots\)" \
    "$openswarm" run -C app --native --world two_apps.json --time 4 --ohc pause@2 --out two_apps
python3 - two_apps/trajectories.csv <<'PY' && passed=$((passed + 1)) || failed=$((failed + 1))
import csv, sys
seen = {}
for row in csv.DictReader(open(sys.argv[1])):
    key = ("blinker" if int(row["robot"]) >= 10 else "disperse", float(row["time_s"]) > 2.1)
    seen.setdefault(key, set()).add((row["led_r"], row["led_g"], row["led_b"]))
expected = {("blinker", False): {("0", "0", "3"), ("0", "0", "0")}, ("blinker", True): {("0", "0", "0")}}
bad = [k for k, v in expected.items() if seen.get(k) != v]
bad += [k for k in (("disperse", False),) if not seen[k] <= {("3", "0", "0"), ("0", "3", "0"), ("0", "0", "0")}
        or ("0", "3", "0") not in seen[k]]
if bad:
    sys.exit(f"FAILED: LED colours {seen} for {bad}")
PY

# Mistakes, each naming the fix.
"$openswarm" build -C app >/dev/null 2>&1
check "the exact mode's firmware in a native world" 2 "asks for \"fidelity\": \"native\".*openswarm build --native" \
    "$sim" --world native.json --time 1 app/build/kilobot/app.elf
check "a shared object that is no robot" 2 "no native robot.*openswarm build --native" \
    "$sim" --time 1 /lib/x86_64-linux-gnu/libm.so.6
check "--gdb in the native mode" 2 "--gdb: the native mode runs the app on the host.*without --native" \
    "$openswarm" run -C app --native --gdb 1234
check "--trace in the native mode (the simulator)" 2 "--trace measures the simulated MCU.*exact mode" \
    "$sim" --trace --time 1 app/build/kilobot-native/app.so
check "--native --debug" 2 "--debug and --native: give one" "$openswarm" build -C app --native --debug
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
