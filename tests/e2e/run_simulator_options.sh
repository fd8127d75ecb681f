#!/usr/bin/env bash
# End to end: `openswarm run` hands the simulator what it is given - the
# overhead controller's messages, the profiler, the IR log, the robots'
# clock spread, the IR loss, and anything after --.
#   run_simulator_options.sh OPENSWARM WORKDIR
set -euo pipefail
openswarm=$1 work=$2
rm -rf "$work" && mkdir -p "$work" && cd "$work"
"$openswarm" new app --template kilolib >/dev/null
cd app
# The template blinks blue; SLEEP at 0.5 s stops the program, so the LED
# changes no more after it.
"$openswarm" run --time 1.5 --ohc sleep@0.5 --profile -- --uid 7 >run.log 2>&1
grep -q "profile of [0-9]* cycles, by function" run.log
grep -q "(asleep)" run.log
last=$(grep -o "^\[ *[0-9.]* s\] led" run.log | tail -1 | grep -o "[0-9.]*" | head -1)
awk -v t="$last" 'BEGIN { exit !(t <= 0.55) }' || { echo "the LED changed at $last s, after SLEEP"; cat run.log; exit 1; }
# Two robots with clocks up to 1% fast or slow: the blue LED, off at 0.5 s
# of each robot's own time, goes off more than 5 ms apart.
"$openswarm" run --time 0.6 --robots 2 --clock-spread 1 >spread.log 2>&1
off() { grep "^\[robot $1\] .* led    red 0 green 0 blue 0" spread.log | grep -o "[0-9]*\.[0-9]*" | head -1; }
awk -v a="$(off 0)" -v b="$(off 1)" 'BEGIN { d = a - b; exit !(d > 0.005 || d < -0.005) }' \
    || { echo "the robots' clocks agree"; cat spread.log; exit 1; }
# The IR log shows the frames a messaging app sends, decoded.
cd .. && "$openswarm" new talk --template disperse >/dev/null && cd talk
"$openswarm" run --time 1.2 --robots 2 --ir-log >air.log 2>&1
grep -q "^\[robot 0\] \[ *[0-9.]* s\] ir     .* crc ok, pulses within [0-9]* cycles of their slots, in range of 1$" air.log \
    || { echo "no decoded frame from robot 0"; cat air.log; exit 1; }
grep -q "led    red 3 green 0 blue 0" air.log || { echo "nobody heard anybody"; cat air.log; exit 1; }
# Every frame lost at the range's edge: frames go out, nobody turns away.
"$openswarm" run --time 1.2 --robots 2 --distance 100 --ir-loss 100 --ir-log >lost.log 2>&1
grep -q " ir     .* crc ok" lost.log
if grep -q "led    red 3" lost.log; then echo "a robot heard a lost frame"; cat lost.log; exit 1; fi
# Another app's firmware on robot 0 (--first): the kilolib app, which
# blinks blue and never talks, stands among two disperse robots; the one it
# runs on says so, and only the disperse robots hear each other and turn red.
"$openswarm" run --time 1.2 --robots 3 --first ../app/build/kilobot/app.elf >first.log 2>&1
grep -q "robot 0 runs .*app/build/kilobot/app.elf; robots 1..2 run .*build/kilobot/talk.elf" first.log \
    || { echo "the simulator was not given both firmware files"; cat first.log; exit 1; }
grep -q "^\[robot 0\] .* led    red 0 green 0 blue 3" first.log || { echo "robot 0 does not blink blue"; cat first.log; exit 1; }
if grep -q "^\[robot 0\] .* led    red 3" first.log; then echo "robot 0 ran the disperse app"; cat first.log; exit 1; fi
grep -q "^\[robot 1\] .* led    red 3 green 0 blue 0" first.log || { echo "robot 1 heard nobody"; cat first.log; exit 1; }
if "$openswarm" run --time 1 --first no-such.elf >first_bad.log 2>&1; then
    echo "a missing --first firmware was accepted"; cat first_bad.log; exit 1
fi
grep -q -- "--first: File does not exist: no-such.elf" first_bad.log || { cat first_bad.log; exit 1; }
# Something the simulator refuses is reported with its own message.
if "$openswarm" run --time 1 -- --light nonsense >bad.log 2>&1; then
    echo "a bad simulator option was accepted"; cat bad.log; exit 1
fi
grep -q -- "--light 'nonsense'" bad.log
# Refused before the build, as bad usage.
status=0
"$openswarm" run --time 1 --clock-spread 9 >spread.log 2>&1 || status=$?
test "$status" -eq 2 || { echo "a clock spread of 9% exited $status, not 2"; cat spread.log; exit 1; }
grep -q -- "--clock-spread 9: give a percentage from 0 to 5" spread.log
# A world's video at the rate asked (before: --video-fps and --video-speed
# were refused, "The following arguments were not expected"): 2 s of the
# talk app's world at 2 simulated seconds a second of video, 5 frames a
# second. Without --video they have nothing to set: refused.
cd ../talk
"$openswarm" run --world worlds/packed.json --out video --time 2 --video --video-fps 5 --video-speed 2 \
    >video.log 2>&1 || { cat video.log; exit 1; }
rate=$(ffprobe -v error -select_streams v:0 -show_entries stream=r_frame_rate -of csv=p=0 video/video.mp4)
[ "$rate" = "5/1" ] || { echo "video.mp4 at $rate frames a second, not 5/1"; cat video.log; exit 1; }
frames=$(ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames -of csv=p=0 video/video.mp4)
[ "$frames" -ge 4 ] && [ "$frames" -le 7 ] || { echo "video.mp4 has $frames frames, not 1 s of 5"; cat video.log; exit 1; }
status=0
"$openswarm" run --world worlds/packed.json --time 1 --video-fps 5 >video.log 2>&1 || status=$?
test "$status" -eq 2 || { echo "--video-fps without --video exited $status, not 2"; cat video.log; exit 1; }
grep -q -- "--video-fps requires --video" video.log || { cat video.log; exit 1; }
echo "1 passed, 0 failed"
