#!/usr/bin/env bash
# End to end: `openswarm experiment` refuses what it cannot do before any
# trial runs - with a message naming the input, the place and the fix, and
# exit status 2 - instead of aborting (status 134) or running trials it
# cannot keep apart. The controller is a stand-in that never runs.
#   experiment_refusals.sh OPENSWARM WORKDIR
set -uo pipefail
openswarm=$1 work=$2
rm -rf "$work" && mkdir -p "$work" && cd "$work"
source "$(dirname "$0")/check.sh"


printf '#!/bin/sh\nexit 1\n' > controller.sh
chmod +x controller.sh

# experiment NAME [CONTROLLER NAME...]: NAME.json with these controllers
# (default: one, "plain"), all running controller.sh.
experiment() {
    local file=$1.json
    shift
    [ $# -gt 0 ] || set -- plain
    local list="" name
    for name in "$@"; do
        list="$list${list:+, }{\"name\": \"$name\", \"program\": \"controller.sh\"}"
    done
    cat > "$file" <<JSON
{
  "arena": {"width_mm": 1000, "height_mm": 1000},
  "marks": {"columns": 3, "rows": 3, "spacing_mm": 250},
  "robots": 1,
  "objects": {"count": 1},
  "duration_s": 10,
  "trials": 2,
  "controllers": [$list]
}
JSON
}

# The results' folder cannot be made: each a message, none an abort.
experiment one
echo "not a folder" > results-file
expect 2 "--out /dev/full: it is a file, not a folder.*give another --out" "$openswarm" experiment one.json --out /dev/full
expect 2 "--out results-file: it is a file, not a folder.*give another --out" "$openswarm" experiment one.json --out results-file
grep -qx "not a folder" results-file && passed=$((passed + 1)) || { failed=$((failed + 1)); echo "FAILED: results-file changed"; }
expect 2 "--out /proc/nope: cannot create the results' folder: .*give an --out folder you can write to" \
    "$openswarm" experiment one.json --out /proc/nope
# A name longer than a file name can hold names the trials' folders.
long=$(printf 'x%.0s' $(seq 300))
experiment long "$long"
expect 2 "long.json: \"controllers\[0\].name\": \"x{40}...\" is 300 bytes long; each trial's folder is named after it.*1..100 bytes" \
    "$openswarm" experiment long.json --out long-results
[ ! -e long-results ] && passed=$((passed + 1)) || { failed=$((failed + 1)); echo "FAILED: long-results was made"; }

# Names that differ only in case, punctuation or accents would share their
# trials' folders (4 trials in 2 folders, each overwriting the other).
experiment case "Plain Loop" "plain-loop"
expect 2 "case.json: \"controllers\[1\].name\": \"plain-loop\" and controllers\[0\].name \"Plain Loop\" would share their trials' folders \(trial-01-plain-loop, ...\): .*differ in a letter or digit" \
    "$openswarm" experiment case.json --out case-results
experiment accents "Café" "Cafè"
expect 2 "accents.json: \"controllers\[1\].name\": \"Cafè\" and controllers\[0\].name \"Café\" would share their trials' folders \(trial-01-caf--, ...\)" \
    "$openswarm" experiment accents.json --out accents-results
[ ! -e case-results ] && [ ! -e accents-results ] && passed=$((passed + 1)) || { failed=$((failed + 1)); echo "FAILED: a refused experiment made its folder"; }

# Trials that would each write more samples than openswarm-sim takes (50
# million rows): refused at once, not trial by trial.
cat > big.json <<'JSON'
{
  "arena": {"width_mm": 4000, "height_mm": 3000},
  "marks": {"columns": 40, "rows": 30, "spacing_mm": 80},
  "robots": 100,
  "objects": {"count": 1000, "radius_mm": 20},
  "duration_s": 86400,
  "sample_period_s": 0.1,
  "trials": 1,
  "controllers": [{"name": "plain", "program": "controller.sh"}]
}
JSON
expect 2 "big.json: \"sample_period_s\": 100 robots and 1000 objects sampled every 0.1 s for 86400 s make 9.5e\\+08 rows of each trial's trajectories.csv and objects.csv; openswarm-sim writes at most 50000000: a sample_period_s of at least 1.91 s, a shorter duration_s, or fewer robots and objects" \
    "$openswarm" experiment big.json --out big-results
sed -i 's/"duration_s": 86400/"duration_s": 3600/' big.json
expect 2 "big.json: \"sample_period_s\": 100 robots and 1000 objects sampled every 0.1 s for 86400 s \\(--duration\\) make 9.5e\\+08 rows" \
    "$openswarm" experiment big.json --duration 86400 --out big-results
[ ! -e big-results ] && passed=$((passed + 1)) || { failed=$((failed + 1)); echo "FAILED: big-results was made"; }

# Numbers that are not finite (nan ran the file's duration, exit 0) or negative.
for bad in nan NaN inf -inf -5 1e999; do
    expect 2 "--duration: '$bad' is not seconds: give a finite number 1..86400, e.g. --duration 600" \
        "$openswarm" experiment one.json --duration "$bad" --out nan-results
done
[ ! -e nan-results ] && passed=$((passed + 1)) || { failed=$((failed + 1)); echo "FAILED: --duration nan ran"; }
expect 2 "--time: 'nan' is not seconds: give a finite number 0.001..3600, e.g. --time 5" "$openswarm" size --time nan

# A key given twice was last-wins, silently (world.json refuses it).
sed 's/"trials": 2,/"trials": 2,\n  "trials": 3,/' one.json > twice.json
expect 2 "twice.json:8:3: \"trials\" is given twice in this object \(also on line 7\): keep one" \
    "$openswarm" experiment twice.json --out twice-results
sed 's/"arena": {"width_mm": 1000, "height_mm": 1000}/"arena": {"width_mm": 1000, "width_mm": 900, "height_mm": 1000}/' one.json > twice-nested.json
expect 2 "twice-nested.json:2:31: \"width_mm\" is given twice in this object \(also on line 2\): keep one" \
    "$openswarm" experiment twice-nested.json --out twice-results

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
