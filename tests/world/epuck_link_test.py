#!/usr/bin/env python3
"""The e-puck world link (ports/epuck/host, openswarm/epuck_world_link.h),
driven as the world simulator drives it: epuck_link_test.py APP, where APP
is tests/world/epuck_link_app.c built for PORT epuck_world.

Checks: the first output (time 0, before any input); the camera handler's
wheel speeds through the wheels' ramp (200 steps/s per command); the
robot's time advances by exactly each step's advance_ms; the RGB LEDs
toggle every 500 ms, to the millisecond; STOP gets a last answer, the
kernel's loss counters (all 0) and exit 0; a bad magic or the end of input exit 2 with a message naming what was
read; two runs give the same bytes; robot_id() is the id the world gives
(OPENSWARM_ROBOT_ID)."""
import os
import struct
import subprocess
import sys

MAGIC = 0x314B5045
STOP = 2
PROXIMITY = 1
INPUT = struct.Struct("<IIHH8H8HHH")
OUTPUT = struct.Struct("<IIhhBBBBI")
LOSSES_MAGIC = 0x4C4B5045  # "EPKL": after STOP's answer, the kernel's 12 loss counters
LOSSES = struct.Struct("<I12H")
GREEN, RED, WHITE = 0x07E0, 0xF800, 0xFFFF
LED_ON = 0x0C  # EPUCK_RGB(0, 3, 0)

failures = []


def check(condition, what):
    if not condition:
        failures.append(what)
        print(f"FAIL {what}")


class Robot:
    """One robot process, in lockstep: every input gets one output."""

    def __init__(self, app):
        # As the world starts it: its index in the world is its id (robot_id()).
        self.process = subprocess.Popen([app], stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                        stderr=subprocess.PIPE, env=dict(os.environ, OPENSWARM_ROBOT_ID="7"))
        self.transcript = b""
        self.time = 0

    def output(self):
        raw = self.process.stdout.read(OUTPUT.size)
        if len(raw) != OUTPUT.size:
            sys.exit(f"the robot answered {len(raw)} bytes, not {OUTPUT.size}; stderr:\n"
                     + self.process.stderr.read().decode())
        self.transcript += raw
        return dict(zip(("magic", "time", "left", "right", "ring", "body", "front", "rgb",
                         "faults"), OUTPUT.unpack(raw)))

    def send(self, advance_ms, flags=0, selector=0, pixel=None, magic=MAGIC, proximity=0):
        width, height = (40, 30) if pixel is not None else (0, 0)
        message = INPUT.pack(magic, advance_ms, flags, selector, *([proximity] * 16), width,
                             height)
        if pixel is not None:
            message += struct.pack("<H", pixel) * (width * height)
        self.process.stdin.write(message)
        self.process.stdin.flush()

    def step(self, advance_ms, **inputs):
        self.send(advance_ms, **inputs)
        out = self.output()
        self.time += advance_ms
        check(out["magic"] == MAGIC, f"output magic {out['magic']:#x}")
        check(out["time"] == self.time, f"time {out['time']} after advancing to {self.time}")
        check(out["faults"] == 0, f"{out['faults']} faults at {self.time} ms")
        return out

    def finish(self):
        """Close the link's input; the exit status, what else the robot wrote, its stderr."""
        self.process.stdin.close()
        rest = self.process.stdout.read()
        err = self.process.stderr.read().decode()
        return self.process.wait(timeout=30), rest, err


def wheels(out):
    return (out["left"], out["right"])


def frames(robot, pixel, expected_ramp):
    """One frame per 100 ms step: the wheels after each command."""
    got = [wheels(robot.step(100, pixel=pixel)) for _ in expected_ramp]
    check(got == expected_ramp, f"frames of {pixel:#06x}: wheels {got}, expected {expected_ramp}")


def led_at(robot, advance_ms, expected):
    out = robot.step(advance_ms)
    check(out["rgb"] == expected, f"RGB LEDs {out['rgb']:#x} at {robot.time} ms, expected {expected:#x}")


def full_run(app):
    robot = Robot(app)
    first = robot.output()
    check(first["magic"] == MAGIC and first["time"] == 0 and wheels(first) == (0, 0),
          f"first output {first}: expected time 0, wheels 0")
    check(first["rgb"] == LED_ON, "the blinker lights the LEDs at once")
    # Seen a robot: 890/530, 200 steps/s per command from a standstill.
    frames(robot, GREEN, [(200, 200), (400, 400), (600, 530), (800, 530), (890, 530)])
    check(robot.time == 500, "five frames are 500 ms")
    # An object: 980/500, one command away.
    frames(robot, RED, [(980, 500)])
    # Nothing (a white wall): 550/990, three commands away.
    frames(robot, WHITE, [(780, 700), (580, 900), (550, 990)])
    # Inputs without a frame change nothing the app does; time still only moves by advance_ms.
    out = robot.step(0, flags=PROXIMITY, selector=3, proximity=1000)
    check(wheels(out) == (550, 990), "a step of 0 ms with proximity and selector keeps the wheels")
    # The blinker: on for [0, 500), off for [500, 1000), on from 1000 ...
    led_at(robot, 99, 0)   # 999
    led_at(robot, 1, LED_ON)  # 1000
    led_at(robot, 499, LED_ON)  # 1499
    led_at(robot, 1, 0)  # 1500
    robot.send(10, flags=STOP)
    last = robot.output()
    check(last["time"] == robot.time + 10, f"STOP's answer at {last['time']} ms, expected {robot.time + 10}")
    status, rest, err = robot.finish()
    # Then its kernel's losses (the world's warnings), none here, and nothing more.
    losses = LOSSES.unpack(rest[:LOSSES.size]) if len(rest) == LOSSES.size else None
    check(status == 0 and losses == (LOSSES_MAGIC,) + (0,) * 12,
          f"after STOP: exit {status}, {len(rest)} more bytes ({rest!r}, not the losses), stderr {err!r}")
    check("e-puck 7 here" in err, f"the app's robot_id() is not the 7 it was given: stderr {err!r}")
    return robot.transcript


def broken_link(app, what, feed, message):
    robot = Robot(app)
    robot.output()
    feed(robot)
    status, _, err = robot.finish()
    check(status == 2 and message in err, f"{what}: exit {status}, stderr {err!r}")


def bad_magic(robot):
    robot.send(100, magic=0xDEADBEEF)


def no_input(robot):
    """Nothing: finish() closes the input."""


def main():
    app = sys.argv[1]
    first = full_run(app)
    second = full_run(app)
    check(first == second, "two runs differ")
    broken_link(app, "bad magic", bad_magic, "0xDEADBEEF")
    broken_link(app, "end of input", no_input, "ended after 0 of")
    print(f"{len(first) // OUTPUT.size} outputs per run; "
          f"{'all passed' if not failures else f'{len(failures)} failed'}")
    sys.exit(1 if failures else 0)


main()
