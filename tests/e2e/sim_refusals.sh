#!/usr/bin/env bash
# End to end: openswarm-sim refuses what it cannot do before it opens any
# output - with a message naming the input, the place and the fix, and a
# non-zero exit status (2 for bad input) - and fails when an output cannot
# be written.
#   sim_refusals.sh OPENSWARM-SIM AVR-TESTS-DIR EPUCK-CONTROLLER WORKDIR
set -uo pipefail
sim=$1 elf=$2/kilolib_blink.elf epuck=$3 work=$4
rm -rf "$work" && mkdir -p "$work" && cd "$work"
source "$(dirname "$0")/check.sh"

# holds DESCRIPTION COMMAND...: the command succeeds.
holds() {
    local what=$1
    shift
    if "$@"; then passed=$((passed + 1)); else failed=$((failed + 1)); echo "FAILED: $what"; fi
}

cat > kilobots.json <<'JSON'
{
  "arena": {"width_mm": 500, "height_mm": 500},
  "duration_s": 0.2,
  "robots": [{"poses": [{"x_mm": 100, "y_mm": 100}]}]
}
JSON
cat > epucks.json <<'JSON'
{
  "robot": "epuck",
  "arena": {"width_mm": 1000, "height_mm": 1000},
  "duration_s": 0.2,
  "robots": [{"poses": [{"x_mm": 300, "y_mm": 300}]}]
}
JSON

# --video without ffmpeg on the PATH: refused before the outputs are
# opened (a previous run's trajectories.csv was truncated).
"$sim" --quiet --no-progress --world kilobots.json --out run "$elf" || { echo "FAILED: a plain run"; exit 1; }
cp run/trajectories.csv kept.csv
mkdir -p empty-bin
for world in kilobots.json epucks.json; do
    program=$elf
    [ "$world" = epucks.json ] && program=$epuck
    expect 2 "--video needs ffmpeg: apt-get install ffmpeg, or drop --video \\(none in the PATH.s folders: .*empty-bin\\)" \
        env PATH="$PWD/empty-bin" "$sim" --quiet --no-progress --world "$world" --out run --video "$program"
    holds "--video without ffmpeg changed run/trajectories.csv ($world)" cmp -s kept.csv run/trajectories.csv
done
expect 2 "--video records the run into --out DIR's video.mp4: give --out DIR too" \
    "$sim" --quiet --no-progress --world kilobots.json --video "$elf"
expect 2 "--video-fps and --video-speed set the rate of --video's video.mp4: give --video too, or drop them" \
    "$sim" --quiet --no-progress --world kilobots.json --out run --video-fps 10 "$elf"
expect 2 "--video-speed '0': expected a number from 0.01 to 10000, e.g. --video-speed 10" \
    "$sim" --quiet --no-progress --world kilobots.json --out run --video --video-speed 0 "$elf"
expect 2 "--ids numbers the robots in --out DIR's final.png: give --out DIR too, or drop --ids" \
    "$sim" --quiet --no-progress --world kilobots.json --ids "$elf"

# An output that is the same file as an input: the input would be
# overwritten (a world file named trajectories.csv, --out .).
cp kilobots.json trajectories.csv
expect 2 "--out \\.: its trajectories.csv is the world file trajectories.csv: the run would overwrite it; give another --out folder, or rename the world file" \
    "$sim" --quiet --no-progress --world trajectories.csv --out . "$elf"
holds "--out . overwrote the world file trajectories.csv" cmp -s kilobots.json trajectories.csv
mkdir -p sub
expect 2 "--out sub/\\.\\./: its trajectories.csv is the world file \\./trajectories.csv" \
    "$sim" --quiet --no-progress --world ./trajectories.csv --out sub/../ "$elf"
holds "--out sub/../ overwrote the world file" cmp -s kilobots.json trajectories.csv
cp "$elf" robot.elf
ln -s robot.elf link.elf
for option in --trace-csv --vcd; do
    expect 2 "$option link.elf is robot 0's firmware robot.elf: the run would overwrite it; give $option another file" \
        "$sim" --quiet --no-progress --time 0.1 "$option" link.elf robot.elf
done
expect 2 "--console-csv link.elf is robot 0's firmware robot.elf: the run would overwrite it; give --console-csv another file" \
    "$sim" --quiet --no-progress --time 0.1 --console-csv link.elf robot.elf
expect 2 "--fault-log robot.elf is robot 0's firmware robot.elf: the run would overwrite it; give --fault-log another file" \
    "$sim" --quiet --no-progress --time 0.1 --faults reset=1 --fault-log robot.elf robot.elf
printf '0 0\n' > at.txt
expect 2 "--trace-csv at.txt is the --positions file at.txt: the run would overwrite it; give --trace-csv another file" \
    "$sim" --quiet --no-progress --time 0.1 --positions at.txt --trace-csv at.txt robot.elf
cp epucks.json objects.csv
expect 2 "--out \\.: its objects.csv is the world file objects.csv: the run would overwrite it" \
    "$sim" --quiet --no-progress --world objects.csv --out . "$epuck"
holds "--out . overwrote the e-puck world file objects.csv" cmp -s epucks.json objects.csv
holds "an output overwrote robot.elf" cmp -s "$elf" robot.elf
holds "an output overwrote at.txt" grep -qx "0 0" at.txt

# A run that would write more samples than the documented limit (50
# million rows of trajectories.csv and objects.csv): refused at once, with
# the numbers and the fix (it was accepted: about 360 GB of CSV). timeout:
# before the fix this ran for a million simulated seconds.
cat > long.json <<'JSON'
{
  "arena": {"width_mm": 500, "height_mm": 500},
  "duration_s": 1e6,
  "sample_period_s": 0.001,
  "robots": [{"poses": [{"x_mm": 100, "y_mm": 100}]}],
  "objects": [{"x_mm": 300, "y_mm": 300, "radius_mm": 20}]
}
JSON
sed 's/"arena"/"robot": "epuck", "arena"/' long.json > long-epucks.json
expect 2 "--out long: 1 robot and 1 object sampled every 0.001 s for 1e\\+06 s make 2e\\+09 rows of trajectories.csv and objects.csv \\(about 65 GB\\); at most 50000000 are written: a sample_period_s of at least 0.0401 s in long.json, a shorter run \\(--time or duration_s\\), or no --out" \
    timeout 60 "$sim" --quiet --no-progress --world long.json --out long "$elf"
holds "a refused run made its --out folder" test ! -e long
expect 2 "--out long: 1 robot and 1 object sampled every 0.001 s for 30000 s make 6e\\+07 rows" \
    timeout 60 "$sim" --quiet --no-progress --world long.json --time 30000 --out long "$elf"
expect 2 "--out long: 1 e-puck and 1 object sampled every 0.001 s" \
    timeout 60 "$sim" --quiet --no-progress --world long-epucks.json --out long "$epuck"

# A write that fails fails the run, naming the file (each exited 0, the
# trace or log lost). /dev/full takes the open and refuses every write.
expect 2 "--trace-csv /dev/full: cannot write it: No space left on device" \
    "$sim" --quiet --no-progress --time 2 --trace-csv /dev/full "$elf"
expect 2 "--vcd /dev/full: cannot write it: No space left on device" \
    "$sim" --quiet --no-progress --time 2 --vcd /dev/full "$elf"
expect 2 "--fault-log /dev/full: cannot write it: No space left on device" \
    "$sim" --quiet --no-progress --time 2 --faults reset:0@0.5,brownout:0@1 --fault-log /dev/full "$elf"
err=$("$sim" --no-progress --time 2 --trace "$elf" 2>&1 >/dev/full)
status=$?
if [ "$status" -eq 2 ] && printf '%s' "$err" | grep -q "the standard output: cannot write it: No space left on device"; then
    passed=$((passed + 1))
else
    failed=$((failed + 1))
    echo "FAILED: --trace > /dev/full -> exit $status (expected 2), stderr:"
    printf '%s\n' "$err"
fi

# --faults: a fault given twice (the last won), an empty list (exit 2, no
# message), a fault after the run's end (nothing injected, exit 0).
expect 2 "--faults 'drift:0=2,drift:0=-3': drift:0 is given twice \\(drift:0=2 and drift:0=-3\\): keep one" \
    "$sim" --quiet --no-progress --time 0.1 --faults drift:0=2,drift:0=-3 "$elf"
expect 2 "--faults 'reset=3': reset= is given twice \\(reset=2 and reset=3\\): keep one" \
    "$sim" --quiet --no-progress --time 0.1 --faults reset=2 --faults reset=3 "$elf"
expect 2 "--faults 'reset:0@1,reset:0@1': reset:0@1 is given twice" \
    "$sim" --quiet --no-progress --time 2 --faults reset:0@1,reset:0@1 "$elf"
expect 2 "--faults 'blank:0,blank:0': blank:0 is given twice" \
    "$sim" --quiet --no-progress --time 0.1 --faults blank:0,blank:0 "$elf"
expect 2 "--faults '': an empty list; expected a comma-separated list of reset=PER_HOUR" \
    "$sim" --quiet --no-progress --time 0.1 --faults "" "$elf"
expect 2 "--faults reset:0@5: at 5 s, after the end of the run \\(1 s\\): give a time within it, or a longer --time" \
    "$sim" --quiet --no-progress --time 1 --faults reset:0@5 "$elf"
expect 2 "--faults brownout:0@0.5: at 0.5 s, after the end of the run \\(0.2 s\\)" \
    "$sim" --quiet --no-progress --world kilobots.json --faults brownout:0@0.5 "$elf"
holds "two resets at different times are two faults" \
    "$sim" --quiet --no-progress --time 2 --faults reset:0@0.5,reset:0@1 "$elf"

# An e-puck world with options only a Kilobot's simulated MCU and IR
# understand: refused by name (each was ignored, exit 0).
kilobot_only() {
    local name=$1
    shift
    expect 2 "$name: Kilobots only \\(their simulated MCU, IR or overhead controller\\), and epucks.json holds e-pucks: drop $name" \
        "$sim" --quiet --no-progress --world epucks.json "$@" "$epuck"
}
kilobot_only --ohc --ohc run@0.1
kilobot_only --counters --counters 0
kilobot_only --ir-log --ir-log
kilobot_only --clock-spread --clock-spread 1
kilobot_only --ir-range --ir-range 50
kilobot_only --ir-loss --ir-loss 5
kilobot_only --trace --trace
kilobot_only --trace-csv --trace-csv t.csv
kilobot_only --vcd --vcd t.vcd
kilobot_only --marks --marks
kilobot_only --timestamps --timestamps
kilobot_only --charging --charging
kilobot_only --voltage --voltage 3000
kilobot_only --faults --faults reset=1
holds "a refused e-puck run wrote t.csv or t.vcd" test ! -e t.csv -a ! -e t.vcd
holds "an e-puck world with its own options runs" \
    "$sim" --quiet --no-progress --world epucks.json --time 0.1 "$epuck"

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
