#!/usr/bin/env python3
"""A stand-in for the Kilobot overhead controller on a pseudo-terminal.

Writes the terminal's name to PORT_FILE, then reads 132-byte packets as the
real controller would (0x55, a kind, 129 bytes, XOR check) and checks the
upload in them against HEX, parsed here on its own: Bootload, then for each
round the page count and every page byte for byte, then Stop. Prints what
it got; exits 0 only if every packet was right.

  fake_ohc.py PORT_FILE HEX ROUNDS      check an upload
  fake_ohc.py PORT_FILE --mute          read nothing (a port nobody drains)
"""
import os
import pty
import sys
import time
import tty

PACKET = 132
PAGE = 128


def flash_of(hex_file):
    """Flash bytes from address 0 (0xFF where the file sets none)."""
    memory, base = {}, 0
    for line in open(hex_file):
        line = line.strip()
        if not line:
            continue
        raw = bytes.fromhex(line[1:])
        count, address, kind = raw[0], raw[1] << 8 | raw[2], raw[3]
        assert sum(raw) % 256 == 0, "bad checksum in " + line
        if kind == 0:
            for i in range(count):
                memory[base + address + i] = raw[4 + i]
        elif kind == 2:
            base = (raw[4] << 8 | raw[5]) << 4
        elif kind == 4:
            base = (raw[4] << 8 | raw[5]) << 16
        elif kind == 1:
            break
    size = max(memory) + 1 if memory else 0
    return bytes(memory.get(a, 0xFF) for a in range(size))


def read_packet(master, deadline):
    data = b""
    while len(data) < PACKET:
        if time.time() > deadline:
            sys.exit("fake OHC: FAIL: timed out after %d bytes of a packet" % len(data))
        try:
            chunk = os.read(master, PACKET - len(data))
        except OSError:
            sys.exit("fake OHC: FAIL: the port closed in the middle of the upload")
        data += chunk
    if data[0] != 0x55:
        sys.exit("fake OHC: FAIL: packet starts with 0x%02x, not 0x55" % data[0])
    check = 0
    for b in data[:-1]:
        check ^= b
    if check != data[-1]:
        sys.exit("fake OHC: FAIL: XOR check 0x%02x, the packet says 0x%02x" % (check, data[-1]))
    return data


def expect(cond, what):
    if not cond:
        sys.exit("fake OHC: FAIL: " + what)


def main():
    master, slave = pty.openpty()
    tty.setraw(master)
    with open(sys.argv[1] + ".tmp", "w") as f:
        f.write(os.ttyname(slave))
    os.rename(sys.argv[1] + ".tmp", sys.argv[1])
    if sys.argv[2] == "--mute":
        time.sleep(120)
        return
    flash, rounds = flash_of(sys.argv[2]), int(sys.argv[3])
    pages = (len(flash) + PAGE - 1) // PAGE
    deadline = time.time() + 60 + rounds * pages * 1.0
    p = read_packet(master, deadline)
    expect(p[1] == 2 and p[11] == 0x80, "first packet is not Bootload (kind 2, message 0x80)")
    for r in range(rounds):
        p = read_packet(master, deadline)
        expect(p[1] == 2 and p[11] == 0x82, "round %d: no page count message (0x82)" % (r + 1))
        expect(p[2] == pages, "round %d: page count %d, the .hex has %d" % (r + 1, p[2], pages))
        for page in range(pages):
            p = read_packet(master, deadline)
            expect(p[1] == 4, "round %d: packet kind %d where page %d should be" % (r + 1, p[1], page))
            expect(p[2] == page, "round %d: page %d where page %d should be" % (r + 1, p[2], page))
            want = flash[page * PAGE:(page + 1) * PAGE].ljust(PAGE, b"\xff")
            for i in range(PAGE):
                expect(p[3 + i] == want[i], "page %d byte %d: 0x%02x, the .hex has 0x%02x"
                       % (page, i, p[3 + i], want[i]))
    p = read_packet(master, deadline)
    expect(p[1] == 0, "no Stop packet after the last round")
    print("fake OHC: %d rounds of %d pages, every byte as in the .hex" % (rounds, pages))


main()
