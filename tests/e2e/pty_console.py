#!/usr/bin/env python3
"""A robot's serial port stand-in: a pseudo-terminal whose other end gives
what this program reads on standard input (a simulator's console).

Writes the terminal's name to PORT_FILE, waits for START_FILE to exist (the
monitor has opened the port: what came before its open would be flushed),
copies standard input to the terminal, then holds it open until killed.

  openswarm-sim ... | pty_console.py PORT_FILE START_FILE
"""
import os
import pty
import sys
import time
import tty

master, slave = pty.openpty()
tty.setraw(master)
with open(sys.argv[1] + ".tmp", "w") as f:
    f.write(os.ttyname(slave))
os.rename(sys.argv[1] + ".tmp", sys.argv[1])
while not os.path.exists(sys.argv[2]):
    time.sleep(0.05)
for chunk in iter(lambda: sys.stdin.buffer.read1(4096), b""):
    os.write(master, chunk)
time.sleep(600)
