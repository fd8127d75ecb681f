#!/usr/bin/env bash
# End to end: a FIFO (named pipe) given where a file is read is refused,
# naming it, before it is opened - open() of a FIFO waits for a writer, and
# openswarm-sim blocked there forever (issue 30). Every command runs under
# a generous timeout, so that a hang fails the test instead of blocking it.
#   fifo_inputs.sh OPENSWARM-SIM OPENSWARM AVR-TESTS-DIR WORKDIR
set -uo pipefail
sim=$1 openswarm=$2 elf=$3/kilolib_blink.elf work=$4
rm -rf "$work" && mkdir -p "$work" && cd "$work"
source "$(dirname "$0")/check.sh"
limit=60 # seconds; each command below takes well under one

mkfifo pipe
cat > world.json <<'JSON'
{
  "arena": {"width_mm": 500, "height_mm": 500},
  "duration_s": 0.1,
  "robots": [{"poses": [{"x_mm": 100, "y_mm": 100}]}]
}
JSON
cat > names-pipe.json <<'JSON'
{
  "arena": {"width_mm": 500, "height_mm": 500},
  "duration_s": 0.1,
  "robots": [{"poses": [{"x_mm": 100, "y_mm": 100}], "firmware": "pipe"}]
}
JSON

fifo="is a FIFO \\(named pipe\\), which would wait for a writer forever, not a regular file"
expect 2 "the firmware pipe $fifo: give the FIRMWARE.elf" timeout $limit "$sim" --quiet --no-progress pipe
expect 2 "the firmware pipe $fifo" timeout $limit "$sim" --quiet --no-progress "$elf" pipe
expect 2 "--world pipe $fifo: give the world.json file itself" \
    timeout $limit "$sim" --quiet --no-progress --world pipe "$elf"
expect 2 "--positions pipe $fifo: give a text file" \
    timeout $limit "$sim" --quiet --no-progress --positions pipe "$elf"
expect 2 "names-pipe.json:4:66: robots\\[0\\].firmware: \"pipe\": not a file" \
    timeout $limit "$sim" --quiet --no-progress --world names-pipe.json
expect 2 "--world \\. is a folder, not a regular file" timeout $limit "$sim" --quiet --no-progress --world . "$elf"

# The tool: an experiment file, an app's openswarm.json, a test's file.
expect 2 "pipe: a FIFO \\(named pipe\\), which would wait for a writer forever, not a regular file; give an experiment file" \
    timeout $limit "$openswarm" experiment pipe
mkdir -p app
mkfifo app/openswarm.json
expect 2 "app/openswarm.json: a FIFO \\(named pipe\\).*move it away" timeout $limit "$openswarm" build -C app
"$openswarm" new tested >/dev/null || { echo "FAILED: openswarm new tested"; exit 1; }
mkdir -p tested/tests && mkfifo tested/tests/pipe.trace
expect 2 "tested/tests/pipe.trace: a FIFO \\(named pipe\\).*move it out of tests/" \
    timeout $limit "$openswarm" test -C tested

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
