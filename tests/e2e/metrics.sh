#!/usr/bin/env bash
# End to end: `openswarm metrics` on a Kilobot world run. Three robots stand
# still at (100, 100), (150, 100) and (100, 200) for 3 s with a lamp at
# (100, 0); their firmware (metrics/reporter.c) reports its uid once and
# its blinks every 500 ms as "metric NAME VALUE" lines, and a script
# (metrics/samples.py) counts the samples. Every number checked is known
# by hand; the native mode's run reports the same. Then the mistakes, each
# with its exit status.
#   metrics.sh OPENSWARM OPENSWARM_SIM WORKDIR
set -euo pipefail
openswarm=$1 sim=$2 work=$3 here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work" && mkdir -p "$work" && cd "$work"
fail() { echo "FAILED: $1"; shift; for f in "$@"; do echo "--- $f"; cat "$f"; done; exit 1; }

"$openswarm" new app --template blinky >/dev/null
cp "$here/metrics/reporter.c" app/main.c
sed -i 's/"stack": 96/"stack": 256/' app/openswarm.json # printf needs room
cp "$here/metrics/still.json" world.json
"$openswarm" run -C app --world world.json --out run >run.log 2>&1 || fail "the run" run.log
for f in trajectories.csv console.csv world.json; do test -s "run/$f" || fail "run/$f was not written" run.log; done
grep -Eq '^[0-9.]+,1,"metric uid 2"$' run/console.csv || fail "robot 1's uid line is not in console.csv" run/console.csv

# Built-ins, the firmware's and the script's, into a CSV of our choice.
"$openswarm" metrics run --metric nearest_neighbour_mm --metric largest_group:range_mm=60 \
    --metric light_distance_mm --metric coverage --metric blinks --metric uid \
    --script "$here/metrics/samples.py" --csv values.csv >table.txt 2>errors.txt \
    || fail "openswarm metrics" table.txt errors.txt
expect_row() { grep -Eq "$1" table.txt || fail "no row matching '$1' in the table" table.txt errors.txt; }
expect_row '^nearest_neighbour_mm +66\.6667 +66\.6667 +66\.6667 +7 +built-in$' # (50 + 50 + 100) / 3
expect_row '^largest_group +0\.666667 .* 7 +built-in$'                         # 60 mm links robots 0 and 1 only
expect_row '^light_distance_mm +137\.268 '                                      # (100 + 111.80 + 200) / 3
expect_row '^coverage +0\.046875 '                                              # 3 of 64 cells of 50 mm
expect_row '^blinks +6 +1 +6 +6 +firmware, mean of 3 robots$'                  # at 0, 0.5 ... 2.5 s
expect_row '^ +per robot at end: 0: 1, 1: 2, 2: 3$'                            # the uids
expect_row '^uid +2 '
expect_row "^samples +7 .* script $here/metrics/samples.py$"
expect_row "^robots_sampled +3 +3 +3 +7 "
test ! -s errors.txt || fail "notes where none were due" errors.txt
test ! -e run/metrics.csv || fail "--csv values.csv also wrote run/metrics.csv"
head -1 values.csv | grep -qx 'time_s,metric,robot,value' || fail "the CSV's header" values.csv
grep -qx '0.500,nearest_neighbour_mm,,66.6667' values.csv || fail "nearest_neighbour_mm at 0.5 s" values.csv
grep -Eqx '[0-9.]+,uid,2,3' values.csv || fail "robot 2's uid report" values.csv
grep -qx '3.000,samples,,7' values.csv || fail "the script's end value at the last sample" values.csv
test "$(grep -c ',blinks,,' values.csv)" -eq 6 || fail "blinks' mean at the six samples from 0.5 s" values.csv
test "$(grep -c ',blinks,1,' values.csv)" -eq 6 || fail "robot 1's six blinks reports" values.csv

# Nothing asked: every metric the run allows, metrics.csv in the run, and
# a note for those it does not.
"$openswarm" metrics run >all.txt 2>notes.txt || fail "openswarm metrics run" all.txt notes.txt
for m in nearest_neighbour_mm largest_group coverage light_distance_mm led_agreement blinks uid; do
    grep -q "^$m " all.txt || fail "$m was not measured by default" all.txt
done
grep -q "note: largest_cluster left out: the world run/world.json has no objects" notes.txt || fail "no note" notes.txt
test -s run/metrics.csv || fail "run/metrics.csv was not written" all.txt
"$openswarm" metrics --list | grep -q "^  led_agreement  *share of robots showing the most common LED colour" \
    || fail "--list does not document led_agreement"

# The simulator's --console-csv, quiet: the same file on one thread and on
# three (each window's lines are written in robot order).
for threads in 1 3; do
    "$sim" --quiet --no-progress --threads $threads --world world.json --out "sim$threads" \
        --console-csv "console$threads.csv" app/build/kilobot/app.elf || fail "openswarm-sim --threads $threads"
done
cmp console1.csv console3.csv || fail "console.csv differs between 1 and 3 threads" console1.csv console3.csv
cmp console1.csv run/console.csv || fail "the quiet simulator's console.csv differs from the run's"

# The native mode keeps the robots' lines too: the same reports.
"$openswarm" run -C app --native --world world.json --out native >native.log 2>&1 || fail "the native run" native.log
"$openswarm" metrics native --metric blinks --metric uid >native.txt 2>&1 || fail "metrics of the native run" native.txt
grep -Eq '^blinks +6 +1 +6 +6 +firmware, mean of 3 robots$' native.txt || fail "native blinks" native.txt
grep -Eq '^ +per robot at end: 0: 1, 1: 2, 2: 3$' native.txt || fail "native uids" native.txt

# Mistakes: bad input exits 2, a failing script 1; each message says what
# to do.
expect() {
    local want=$1 regex=$2
    shift 2
    local status=0
    "$@" >bad.log 2>&1 || status=$?
    if [ "$status" -ne "$want" ] || ! grep -Eq -- "$regex" bad.log; then
        echo "FAILED: $* -> exit $status (expected $want), output:"; cat bad.log; exit 1
    fi
}
expect 2 "nowhere: no such folder; give the --out folder of a run" "$openswarm" metrics nowhere
expect 2 'no built-in metric of that name \(did you mean "blinks"\?\); its robots reported blinks, uid' \
    "$openswarm" metrics run --metric blink
expect 2 'largest_group takes range_mm, not "range"' "$openswarm" metrics run --metric largest_group:range=5
expect 2 "compactness: the world run/world.json has no objects" "$openswarm" metrics run --metric compactness
printf '#!/bin/sh\necho "cannot find column x" >&2\nexit 4\n' >broken.sh && chmod +x broken.sh
expect 1 "metric script ./broken.sh failed with exit status 4; the end of what it wrote on standard error:" \
    "$openswarm" metrics run --script ./broken.sh
grep -q "^    cannot find column x$" bad.log && grep -q "Run it by hand to see why: ./broken.sh run" bad.log \
    || { cat bad.log; fail "no stderr tail or next step"; }
printf 'echo x 1\n' >plain.sh
expect 2 "not executable; make it so \(chmod \+x plain.sh\)" "$openswarm" metrics run --script plain.sh
echo "1 passed, 0 failed"
