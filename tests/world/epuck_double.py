#!/usr/bin/env python3
"""A stand-in e-puck controller for the world's tests: it speaks the world
link (ports/epuck/host/include/openswarm/epuck_world_link.h) as the real
board does, and behaves as the environment says:

  EPUCK_WHEELS=L,R   the wheels' steps/s (default 0,0)
  EPUCK_DIE_AT=MS    exit 5 at that time (a controller that crashes)
  EPUCK_GARBAGE=1    answer with a bad record
  EPUCK_LOG=PREFIX   append what it senses to PREFIX<robot's order>.log:
                     "time front_reflected centre_pixel frame red" per step
                     (frame: 1 when a frame came with this step's input;
                     red: the last frame's red pixels in its middle row)
It shows what the camera's centre sees on its RGB LED: red 3 for red,
green 3 for green, all 3 for white, off for dark."""
import os
import struct
import sys

IN = struct.Struct("<IIHH8H8HHH")
OUT = struct.Struct("<IIhhBBBBI")
MAGIC = 0x314B5045
COLOUR = {0xF800: 0x03, 0x07E0: 0x0C, 0xFFFF: 0x3F, 0x0000: 0x00}


def main():
    inp, out = sys.stdin.buffer, sys.stdout.buffer
    left, right = (int(v) for v in os.environ.get("EPUCK_WHEELS", "0,0").split(","))
    die_at = int(os.environ.get("EPUCK_DIE_AT", "-1"))
    log = None
    if "EPUCK_LOG" in os.environ:
        k = 0
        while os.path.exists(f"{os.environ['EPUCK_LOG']}{k}.log"):
            k += 1
        log = open(f"{os.environ['EPUCK_LOG']}{k}.log", "w")
    magic = 0x12345678 if os.environ.get("EPUCK_GARBAGE") else MAGIC
    t, rgb, centre, red = 0, 0, -1, 0
    out.write(OUT.pack(magic, 0, 0, 0, 0, 0, 0, 0, 0))
    out.flush()
    while True:
        record = inp.read(IN.size)
        if len(record) < IN.size:
            sys.exit(3)
        f = IN.unpack(record)
        advance, flags, off, pulsed, w, h = f[1], f[2], f[4:12], f[12:20], f[20], f[21]
        if w:
            pixels = inp.read(2 * w * h)
            at = 2 * ((h // 2) * w + w // 2)
            centre = struct.unpack("<H", pixels[at:at + 2])[0]
            rgb = COLOUR.get(centre, 0)
            row = struct.unpack(f"<{w}H", pixels[2 * (h // 2) * w:2 * (h // 2 + 1) * w])
            red = sum(1 for p in row if p == 0xF800)
        t += advance
        if die_at >= 0 and t >= die_at:
            sys.exit(5)
        if log and advance:
            front = max(off[0] - pulsed[0], off[7] - pulsed[7])
            log.write(f"{t} {front} {centre:#06x} {1 if w else 0} {red}\n")
        out.write(OUT.pack(MAGIC, t, left, right, 0, 0, 0, rgb, 0))
        out.flush()
        if flags & 2:
            sys.exit(0)


main()
