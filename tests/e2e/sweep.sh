#!/usr/bin/env bash
# End to end: `openswarm experiment` of a sweep file (sweep/still.json): a
# Kilobot app (../metrics/reporter.c: it reports "metric blinks N") in a
# world of three still robots, swept over two parameters, two trials each,
# with a built-in metric, the firmware's and a script's - every value known
# by hand. Then: a second run resumes (nothing run again); a sweep killed
# midway resumes to the same results; shards and MPI ranks give them too;
# new metrics are measured without simulating again; a failing trial is
# reported and the rest kept; mistakes exit 2 with the fix.
#   sweep.sh OPENSWARM WORKDIR
set -euo pipefail
openswarm=$1 work=$2 here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work" && mkdir -p "$work" && cd "$work"
source "$here/check.sh"

"$openswarm" new app --template blinky >/dev/null
cp "$here/metrics/reporter.c" app/main.c
sed -i 's/"stack": 96/"stack": 256/' app/openswarm.json # printf needs room
cp "$here/metrics/still.json" world.json
cp "$here/sweep/still.json" sweep.json
cp "$here/metrics/samples.py" "$here/sweep/fussy.py" .

"$openswarm" experiment sweep.json --out a >a.log 2>&1 || fail "the sweep" a.log
grep -q "^Sweeping 4 points x 2 trials = 8 trials of world.json" a.log || fail "the first line" a.log
test "$(grep -c '^\[[0-9]/8\] point [1-4], trial [12]: nearest_neighbour_mm ' a.log)" -eq 8 || fail "progress" a.log
grep -q "^8 of 8 trials done (0 by an earlier run), 0 failed, in .*, 4 plots in a/plots" a.log || fail "summary" a.log
# Parameters in alphabetical order: duration_s, then robot 1's x.
row() { grep -qx "$1" a/summary.csv || fail "no summary row $1" a/summary.csv; }
head -1 a/summary.csv | grep -qx 'point,duration_s,robots\[0\].poses\[1\].x_mm,metric,n,failed,mean,sd,ci95_low,ci95_high' \
    || fail "summary.csv's header" a/summary.csv
row '1,2,150,nearest_neighbour_mm,2,0,66.6667,0,66.6667,66.6667' # (50 + 50 + 100) / 3
row '2,2,200,nearest_neighbour_mm,2,0,100,0,100,100'             # every one 100 mm from the next
row '1,2,150,blinks,2,0,4,0,4,4'                                   # at 0, 0.5, 1 and 1.5 s
row '3,3,150,blinks,2,0,6,0,6,6'                                   # ... and 2, 2.5 s
row '2,2,200,samples,2,0,5,0,5,5'                                  # 0, 0.5 ... 2 s
row '4,3,200,samples,2,0,7,0,7,7'
grep -qx 'point,trial,seed,duration_s,robots\[0\].poses\[1\].x_mm,time_s,metric,value' <(head -1 a/results.csv) \
    || fail "results.csv's header" a/results.csv
grep -qx '4,2,6,3,200,3,blinks,6' a/results.csv || fail "point 4's second trial (seed 6) at its end" a/results.csv
test "$(grep -c ',done,,point-0[1-4]/trial-0[12]$' a/trials.csv)" -eq 8 || fail "trials.csv" a/trials.csv
for m in nearest_neighbour_mm blinks samples robots_sampled; do
    head -c 4 "a/plots/$m.png" | grep -q PNG || fail "a/plots/$m.png is no PNG" a.log
    test -s "a/plots/$m.svg" || fail "a/plots/$m.svg" a.log
done
test -s a/point-04/trial-02/viewer.html || fail "a trial's viewer" a.log
grep -q "^firmware: .*app/build/kilobot/app.elf ([0-9a-f]*)$" a/command.txt || fail "command.txt" a/command.txt

# The same command again: every trial was done; the results the same.
cp a/results.csv first.csv
"$openswarm" experiment sweep.json --out a >again.log 2>&1 || fail "the second run" again.log
grep -q "^8 of 8 trials done (8 by an earlier run), 0 failed" again.log || fail "a resumed run ran again" again.log
cmp first.csv a/results.csv || fail "results changed on a second run"

# Killed after its first trial (one at a time; SIGTERM to the tool and
# its simulator, as a job scheduler sends it, and as a background job
# ignores SIGINT): exit 143, the trials done kept and gathered, the rest
# pending; then run again: the rest runs, the results are those of the
# whole run.
setsid "$openswarm" experiment sweep.json --out b --jobs 1 >b1.log 2>&1 &
group=$!
for _ in $(seq 600); do
    compgen -G "b/point-*/trial-*/outcome.json" >/dev/null && break
    sleep 0.1
done
kill -TERM -- -"$group" 2>/dev/null || true
status=0
wait "$group" || status=$?
test "$status" -eq 143 || fail "the killed sweep: exit $status, not 143 (did it finish before it was killed?)" b1.log
grep -q "^openswarm: interrupted by SIGTERM: [1-7] trials\? not run yet (trials.csv: pending)" b1.log \
    || fail "the killed sweep's last word" b1.log
grep -q ',pending,not run yet,' b/trials.csv || fail "the killed sweep's pending trials" b/trials.csv
"$openswarm" experiment sweep.json --out b >b2.log 2>&1 || fail "the resumed sweep" b2.log
grep -Eq "^8 of 8 trials done \(([1-7]) by an earlier run\)" b2.log || fail "the resumed sweep's count" b2.log
cmp first.csv b/results.csv || fail "a resumed sweep's results differ"

# Two shards (a Slurm array's tasks), then the command alone gathers.
"$openswarm" experiment sweep.json --out c --shard 0/2 >c0.log 2>&1 || fail "shard 0" c0.log
grep -q "^4 of 8 trials done (0 by an earlier run), 0 failed, 4 not run yet" c0.log || fail "shard 0's count" c0.log
grep -q ',pending,not run yet,' c/trials.csv || fail "pending trials in trials.csv" c/trials.csv
"$openswarm" experiment sweep.json --out c --shard 1/2 >c1.log 2>&1 || fail "shard 1" c1.log
"$openswarm" experiment sweep.json --out c >c.log 2>&1 || fail "gathering the shards" c.log
grep -q "^8 of 8 trials done (8 by an earlier run)" c.log || fail "the shards' trials" c.log
cmp first.csv c/results.csv || fail "shards' results differ"

# Two MPI ranks on this machine.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mpirun --oversubscribe -np 2 "$openswarm" experiment sweep.json --out d >d.log 2>&1 || fail "mpirun" d.log
grep -q "^\[rank 1 " d.log && grep -q "^\[rank 0 " d.log || fail "both ranks ran trials" d.log
cmp first.csv d/results.csv || fail "the ranks' results differ"

# Another metric asked for: measured from each trial's outputs, not simulated again.
sed 's/"blinks"\]/"blinks", "largest_group:range_mm=60"]/' sweep.json >more.json
"$openswarm" experiment more.json --out a >more.log 2>&1 || fail "more metrics" more.log
test "$(grep -c 'simulated before, measured again' more.log)" -eq 8 || fail "trials ran again" more.log
row '1,2,150,largest_group,2,0,0.666667,0,0.666667,0.666667'      # 60 mm links robots 0 and 1 only

# A script that fails for the 3 s runs: those four trials fail with its
# reason, the others are kept; once fixed, only they are measured again.
sed 's/"samples.py"/"fussy.py"/' sweep.json >fussy.json
status=0
"$openswarm" experiment fussy.json --out e >e.log 2>&1 || status=$?
test "$status" -eq 1 || fail "a failed trial exits 1, not $status" e.log
grep -q "^4 of 8 trials done (0 by an earlier run), 4 failed" e.log || fail "the failures' count" e.log
grep -q "4 trials failed (trials.csv says why); the others are kept: run the same command again" e.log || fail "advice" e.log
test "$(grep -c ',failed,"measuring it: metric script .*/fussy.py failed with exit status 1' e/trials.csv)" -eq 4 \
    || fail "the reasons" e/trials.csv
test "$(grep -c '^    fussy.py: 3 s is too long for me$' e/trials.csv)" -eq 4 || fail "the script's words" e/trials.csv
grep -q '^1,2,150,fussy,2,0,2,0,2,2$' e/summary.csv || fail "the others' values" e/summary.csv
grep -q '^3,3,150,fussy,0,2,,,,$' e/summary.csv || fail "a failed point's row" e/summary.csv
FUSSY_FIXED=1 "$openswarm" experiment fussy.json --out e >e2.log 2>&1 || fail "the fixed script" e2.log
test "$(grep -c 'simulated before, measured again' e2.log)" -eq 4 || fail "only the failed were measured" e2.log
grep -q '^3,3,150,fussy,2,0,3,0,3,3$' e/summary.csv || fail "the fixed point" e/summary.csv

# Mistakes: each names the file, the place and the fix (exit 2). expect
# (check.sh) counts failures itself.
set +e
bad() { sed "$1" sweep.json >bad.json; }
bad 's/"robots\[0\].poses\[1\].x_mm"/"robots[0].poses[5].x_mm"/'
expect 2 'bad.json: "grid.robots\[0\].poses\[5\].x_mm": the world.s robots\[0\].poses has no item \[5\] \(it holds 3\)' \
    "$openswarm" experiment bad.json --out x
bad 's/"duration_s": \[2, 3\]/"seed": [1, 2]/'
expect 2 '"grid.seed": the seed is not swept: each trial t of a point runs with "seed" \+ t' "$openswarm" experiment bad.json --out x
mkdir -p broken && echo '{"name": 1, "port": "kilobot"}' >broken/openswarm.json
bad 's/"app": "app"/"app": "broken"/'
expect 2 'broken/openswarm.json: "name": expected the app.s name, found number 1' "$openswarm" experiment bad.json --out x
bad 's/"trials": 2/"trails": 2/'
expect 2 'bad.json: "trails": unknown key; expected one of .* \(did you mean "trials"\?\)' "$openswarm" experiment bad.json --out x
bad 's/\[2, 3\]/[2, 2]/'
expect 2 '"grid.duration_s": number 2 is listed twice \(items 0 and 1\): keep one' "$openswarm" experiment bad.json --out x
bad 's/\[150, 200\]/[150, 5000]/'
expect 2 'the simulator refused a trial.s world .*: fix the sweep.s parameters or the world, then run the same command again; finished trials are kept' \
    "$openswarm" experiment bad.json --out x --jobs 1
grep -q ',failed,"the simulator refused the trial.s world.json:' x/trials.csv || fail "the refusal's reason" x/trials.csv
expect 2 '--shard 2/2: give K/N, this shard.s number K from 0 and the number of shards N' \
    "$openswarm" experiment sweep.json --out x --shard 2/2
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
