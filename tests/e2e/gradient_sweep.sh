#!/usr/bin/env bash
# End to end: the gradient template's sweep (experiments/ir_loss.json), one
# trial of 10 s per point: six robots in a line, IR loss 0, 50 and 90% at
# the range's edge. Each robot reports its hop count ("metric hops N") as it
# changes; hops.settled_s is when the last one changed. Without loss the
# counts settle on 0..5 (mean 2.5) within the run. The IR metrics: the
# channel loses nothing without loss, more with more, and the robots
# receive fewer frames.
#   gradient_sweep.sh OPENSWARM WORKDIR
set -euo pipefail
openswarm=$1 work=$2
rm -rf "$work" && mkdir -p "$work" && cd "$work"
source "$(dirname "$0")/check.sh"

"$openswarm" new g --template gradient >/dev/null
"$openswarm" experiment g/experiments/ir_loss.json --trials 1 --duration 10 --out r >r.log 2>&1 || fail "the sweep" r.log
grep -q "^Sweeping 3 points x 1 trial = 3 trials of line.json" r.log || fail "the first line" r.log
grep -q "^3 of 3 trials done (0 by an earlier run), 0 failed" r.log || fail "the trials" r.log
head -1 r/summary.csv | grep -qx 'point,ir.loss_pct,metric,n,failed,mean,sd,ci95_low,ci95_high' || fail "header" r/summary.csv
grep -qx '1,0,hops,1,0,2.5,0,2.5,2.5' r/summary.csv || fail "without loss the counts are 0..5" r/summary.csv
# Settled within the run, after the last robot (5 hops out) heard: a time in 0..10 s.
for point in 1 2 3; do
    line=$(grep "^$point,[0-9]*,hops.settled_s,1,0," r/summary.csv) || fail "point $point settled" r/summary.csv
    awk -F, '{ exit !($6 > 0 && $6 <= 10) }' <<<"$line" || fail "point $point settled at a time in the run: $line" r/summary.csv
done
test "$(grep -c ',hops.settled_s,' r/results.csv)" -ge 3 || fail "settling over time" r/results.csv
# The built-in IR metrics (ir.csv): no loss, the channel lost nothing;
# more loss, more lost and fewer received.
value() { grep "^$1,[0-9]*,$2,1,0," r/summary.csv | cut -d, -f6; }
test "$(value 1 ir_lost_channel)" = 0 || fail "without loss the channel lost no frame" r/summary.csv
awk -v a="$(value 2 ir_lost_channel)" -v b="$(value 3 ir_lost_channel)" 'BEGIN { exit !(a > 0 && b > a) }' ||
    fail "more loss, more frames lost by the channel" r/summary.csv
awk -v a="$(value 1 ir_received)" -v b="$(value 3 ir_received)" 'BEGIN { exit !(a > 10 && b < a) }' ||
    fail "more loss, fewer frames received" r/summary.csv
head -c 4 r/plots/ir_lost_channel.png | grep -q PNG || fail "the IR plot" r.log
head -c 4 r/plots/hops.settled_s.png | grep -q PNG || fail "the plot" r.log
echo "the gradient sweep ran, settled and plotted"
