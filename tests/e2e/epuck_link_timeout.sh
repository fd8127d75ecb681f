#!/usr/bin/env bash
# End to end: an e-puck controller that never answers stops the run after
# the link's wait (OPENSWARM_LINK_TIMEOUT_S, lowered here to 2 s of wall
# time; 60 by default), naming the robot, the controller and what it did
# not answer, exit 3, the controller and its children killed; under
# `openswarm experiment` that trial fails with the reason and the others'
# results are kept (issue 30: both blocked forever). Every command runs
# under a generous timeout, so that a hang fails the test.
#   epuck_link_timeout.sh OPENSWARM-SIM OPENSWARM EPUCK-CONTROLLER WORKDIR
set -uo pipefail
sim=$1 openswarm=$2 good=$3 work=$4
rm -rf "$work" && mkdir -p "$work" && cd "$work"
source "$(dirname "$0")/check.sh"
limit=120 # seconds; each command below takes a few

cat > epucks.json <<'JSON'
{
  "robot": "epuck",
  "arena": {"width_mm": 1000, "height_mm": 1000},
  "duration_s": 0.5,
  "robots": [{"poses": [{"x_mm": 300, "y_mm": 300}]}]
}
JSON
# Never answers, in a child it waits for (killed with it, or the sleep
# would hold the simulator's standard error open).
cat > silent.sh <<'SH'
#!/bin/sh
sleep 1000 &
echo $! > silent.pid
wait
SH
# Answers at start-up, then reads nothing and never answers again.
cat > stuck.sh <<'SH'
#!/bin/sh
printf 'EPK1'
head -c 16 /dev/zero
exec sleep 1000
SH
chmod +x silent.sh stuck.sh

export OPENSWARM_LINK_TIMEOUT_S=2
expect 3 "robot 0's controller .*silent.sh did not answer at start-up \\(its first answer, before any input\\) within 2 s of wall time: .*it was killed and the run stops.*OPENSWARM_LINK_TIMEOUT_S" \
    timeout $limit "$sim" --quiet --no-progress --world epucks.json "$PWD/silent.sh"
# (killed, it may stay a zombie until whoever adopted it reaps it)
state=$([ -s silent.pid ] && ps -o stat= -p "$(cat silent.pid)")
if [ ! -s silent.pid ] || [ -n "$state" ] && [ "${state#Z}" = "$state" ]; then
    failed=$((failed + 1)); echo "FAILED: silent.sh's sleep still runs (or never started)"
    [ -s silent.pid ] && kill "$(cat silent.pid)"
else
    passed=$((passed + 1))
fi
expect 3 "robot 0's controller .*stuck.sh did not answer the step at 0.00 s within 2 s of wall time" \
    timeout $limit "$sim" --quiet --no-progress --world epucks.json "$PWD/stuck.sh"
expect 2 "OPENSWARM_LINK_TIMEOUT_S=soon: expected seconds above 0, at most 86400 .*give e.g. OPENSWARM_LINK_TIMEOUT_S=120, or unset it" \
    env OPENSWARM_LINK_TIMEOUT_S=soon timeout $limit "$sim" --quiet --no-progress --world epucks.json "$good"
expect 0 "" timeout $limit "$sim" --quiet --no-progress --world epucks.json "$good"

# An experiment: the silent controller's trial fails with the reason, the
# working one's results are kept.
cat > mixed.json <<JSON
{
  "arena": {"width_mm": 1000, "height_mm": 1000},
  "marks": {"columns": 3, "rows": 3, "spacing_mm": 250},
  "robots": 1,
  "objects": {"count": 1},
  "duration_s": 1,
  "trials": 1,
  "controllers": [{"name": "good", "program": "$good"}, {"name": "silent", "program": "stuck.sh"}]
}
JSON
check "an experiment with a controller that never answers" 1 \
    "silent, trial 1 .*failed: .*robot 0's controller .*stuck.sh did not answer the step at 0.00 s within 2 s.*1 of 2 trials ran" \
    timeout $limit "$openswarm" experiment mixed.json --out results --jobs 2
grep -q "^1,good," results/results.csv && passed=$((passed + 1)) || { failed=$((failed + 1)); echo "FAILED: good's results were not kept"; }

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
