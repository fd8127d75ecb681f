#!/usr/bin/env bash
# End to end: `openswarm experiment --video` films the trials asked for as
# they run (video.mp4 in the trial's folder, at the video's own rate), in a
# sweep of three still robots (sweep/still.json's app and world), 2 points
# x 2 trials of 2 s. A trial done before without the video (or with
# another rate) runs again for it; its results stay the same; a run
# without --video keeps the videos; bad rates exit 2 naming the option.
#   sweep_video.sh OPENSWARM WORKDIR
set -euo pipefail
openswarm=$1 work=$2 here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work" && mkdir -p "$work" && cd "$work"
source "$here/check.sh"

"$openswarm" new app --template blinky >/dev/null
cp "$here/metrics/reporter.c" app/main.c
sed -i 's/"stack": 96/"stack": 256/' app/openswarm.json # printf needs room
cp "$here/metrics/still.json" world.json
cat >sweep.json <<'JSON'
{
  "app": "app",
  "world": "world.json",
  "duration_s": 2,
  "trials": 2,
  "grid": {"robots[0].poses[1].x_mm": [150, 200]},
  "metrics": ["nearest_neighbour_mm", "blinks"]
}
JSON

frames() {
    ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames -of csv=p=0 "$1"
}
rate() { ffprobe -v error -select_streams v:0 -show_entries stream=r_frame_rate -of csv=p=0 "$1"; }

# The first run without videos: none made.
"$openswarm" experiment sweep.json --out a >plain.log 2>&1 || fail "the sweep without --video" plain.log
test -z "$(find a -name video.mp4)" || fail "a video without --video" plain.log
cp a/results.csv plain.csv

# Only the second trials, 10 frames a second at real time: 2 s = 20 frames.
"$openswarm" experiment sweep.json --out a --video --video-trials 2 --video-fps 10 >v2.log 2>&1 \
    || fail "the sweep with --video-trials 2" v2.log
grep -q "^4 of 4 trials done (2 by an earlier run), 0 failed, .*(video.mp4 in 2 of them)$" v2.log \
    || fail "the summary: the first trials reused, the second ones filmed" v2.log
for p in 01 02; do
    test ! -e "a/point-$p/trial-01/video.mp4" || fail "point $p's first trial was filmed" v2.log
    v=a/point-$p/trial-02/video.mp4
    test "$(rate "$v")" = "10/1" || fail "$v at $(rate "$v") frames a second, not 10" v2.log
    n=$(frames "$v")
    test "$n" -ge 19 && test "$n" -le 21 || fail "$v has $n frames, not 2 s x 10" v2.log
done
cmp plain.csv a/results.csv || fail "filming changed the results"

# Every trial at the same rate: the second ones are done; the first run
# again, for their video.
"$openswarm" experiment sweep.json --out a --video --video-fps 10 >all.log 2>&1 || fail "the sweep with --video" all.log
grep -q "^4 of 4 trials done (2 by an earlier run), 0 failed, .*(video.mp4 in 4 of them)$" all.log \
    || fail "the summary: the first trials filmed too" all.log
test "$(grep -c 'trial 2: done before' all.log)" -eq 2 || fail "the filmed trials ran again" all.log
# Another rate: all run again, each video at its new rate.
"$openswarm" experiment sweep.json --out a --video --video-fps 5 --video-speed 2 >half.log 2>&1 \
    || fail "the sweep at 5 frames a second, 2x" half.log
grep -q "^4 of 4 trials done (0 by an earlier run)" half.log || fail "a new rate reused old videos" half.log
n=$(frames a/point-01/trial-01/video.mp4)
test "$n" -ge 4 && test "$n" -le 6 || fail "2 s at 2x and 5 frames a second makes 5 frames, not $n" half.log
# Without --video: everything done before, the videos kept.
"$openswarm" experiment sweep.json --out a >kept.log 2>&1 || fail "the sweep without --video again" kept.log
grep -q "^4 of 4 trials done (4 by an earlier run)" kept.log || fail "dropping --video ran trials again" kept.log
test "$(find a -name video.mp4 | wc -l)" -eq 4 || fail "the videos were not kept" kept.log
cmp plain.csv a/results.csv || fail "the results changed"

# Mistakes: exit 2, the option named.
refused() {
    local what=$1 pattern=$2
    shift 2
    status=0
    "$openswarm" experiment sweep.json --out a "$@" >bad.log 2>&1 || status=$?
    test "$status" -eq 2 || fail "$what: exit $status, not 2" bad.log
    grep -q -- "$pattern" bad.log || fail "$what: no word of $pattern" bad.log
}
refused "--video-fps without --video" "--video-fps requires --video" --video-fps 5
refused "a rate of 500" "--video-fps" --video --video-fps 500
refused "trial 0" "--video-trials" --video --video-trials 0
echo "sweep_video: every check passed"
