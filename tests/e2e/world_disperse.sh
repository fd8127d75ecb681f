#!/usr/bin/env bash
# End to end: the disperse template's packed world through `openswarm run
# --world`. Ten robots start packed in a 12 cm square; after the world's
# 120 s their mean nearest-neighbour distance has grown by half or more, and
# the picture and the viewer are there. Then the mistakes --world refuses.
#   world_disperse.sh OPENSWARM WORKDIR
set -euo pipefail
openswarm=$1 work=$2
rm -rf "$work" && mkdir -p "$work" && cd "$work"
"$openswarm" new app --template disperse >/dev/null

# From outside the app (-C): --world is from the current folder, the default
# --out is under the app; no --time, so the world's duration_s (120 s) runs.
"$openswarm" run -C app --world app/worlds/packed.json >run.log 2>&1 || { cat run.log; exit 1; }
grep -q "ran 120.000 s of simulated time (10 robots)" run.log || { echo "not the world's 120 s:"; cat run.log; exit 1; }
grep -q "^Open app/out/packed/viewer.html in a browser, or look at app/out/packed/final.png$" run.log \
    || { echo "no pointer to the viewer:"; cat run.log; exit 1; }
if grep -q " led \| motors " run.log; then echo "traced without --trace:"; cat run.log; exit 1; fi
for f in trajectories.csv final.png viewer.html; do
    test -s "app/out/packed/$f" || { echo "app/out/packed/$f was not written"; cat run.log; exit 1; }
done
python3 "$(dirname "$0")/spread.py" app/out/packed/trajectories.csv 10 120

# --out and --time given: the files go where asked, for the time asked.
"$openswarm" run -C app --world app/worlds/packed.json --out short --time 1 >short.log 2>&1 \
    || { cat short.log; exit 1; }
grep -q "ran 1.000 s of simulated time (10 robots)" short.log || { cat short.log; exit 1; }
test -s short/final.png -a -s short/viewer.html || { echo "--out short was not written"; cat short.log; exit 1; }
# --ids: the same run (the same seed), its robots numbered in final.png.
"$openswarm" run -C app --world app/worlds/packed.json --out short-ids --time 1 --ids >ids.log 2>&1 \
    || { cat ids.log; exit 1; }
cmp -s short/trajectories.csv short-ids/trajectories.csv || { echo "--ids changed the run"; exit 1; }
if cmp -s short/final.png short-ids/final.png; then echo "--ids: final.png has no numbers"; exit 1; fi

# Run again: the last run's outputs are kept beside the new ones (issue 31:
# they were overwritten unseen), the one before them replaced; a folder
# named with --out is overwritten, and that is said.
cp app/out/packed/trajectories.csv first.csv
for again in 1 2; do
    "$openswarm" run -C app --world app/worlds/packed.json --time 1 >again.log 2>&1 || { cat again.log; exit 1; }
    grep -q "^openswarm: the last run's outputs are kept in app/out/packed.last (the one before it is replaced); this run writes app/out/packed$" again.log \
        || { echo "run $again: the last run's move not told"; cat again.log; exit 1; }
done
test -s app/out/packed/final.png || { echo "the new run wrote no app/out/packed/final.png"; exit 1; }
cmp -s app/out/packed.last/trajectories.csv app/out/packed/trajectories.csv \
    || { echo "app/out/packed.last is not the 1 s run before the last"; exit 1; }
if cmp -s first.csv app/out/packed.last/trajectories.csv; then echo "the 120 s run was kept twice"; exit 1; fi
"$openswarm" run -C app --world app/worlds/packed.json --out short --time 1 >again.log 2>&1 || { cat again.log; exit 1; }
grep -q "^openswarm: short holds the outputs of an earlier run: this run's replace them" again.log \
    || { echo "the overwrite of --out short not told"; cat again.log; exit 1; }

# Mistakes: bad usage (exit 2), refused before building, with the file
# and what to do.
expect() {
    local regex=$1
    shift
    local status=0
    "$@" >bad.log 2>&1 || status=$?
    if [ "$status" -ne 2 ] || ! grep -Eq -- "$regex" bad.log; then
        echo "FAILED: $* -> exit $status (expected 2), output:"; cat bad.log; exit 1
    fi
}
expect "--world missing.json: no such file .*not from -C app; the app has: app/worlds/packed.json" \
    "$openswarm" run -C app --world missing.json
grep -q "Building\|Built" bad.log && { echo "built before refusing a missing world"; cat bad.log; exit 1; }
expect "--world excludes --robots|--robots excludes --world" "$openswarm" run -C app --world app/worlds/packed.json --robots 3
expect "--world excludes --line|--line excludes --world" "$openswarm" run -C app --world app/worlds/packed.json --line 80
expect "--out requires --world" "$openswarm" run -C app --out x
# A world the simulator refuses: its message (file, line, column, the fix)
# and exit status 2 through the tool too.
printf '{"arena": {"width_mm": 600, "height_mm": 400},\n "robots": [{"count": 3, "reigon": {}}]}\n' >bad_world.json
expect "bad_world.json:2:26: robots\[0\]: unknown key \"reigon\"; did you mean \"region\"\?" \
    "$openswarm" run -C app --world bad_world.json
grep -q "the simulator refused its input" bad.log || { echo "no word from the tool on the refusal"; cat bad.log; exit 1; }
echo "1 passed, 0 failed"
