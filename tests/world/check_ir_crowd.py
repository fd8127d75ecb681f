#!/usr/bin/env python3
"""No frame is refused in a crowd (world_gradient.elf on worlds/crowd.json).

check_ir_crowd.py SIM ELF WORLD SECONDS: 9 robots in range of each other
send every half second each; a robot then hears frames back to back, each
4.4 ms with interrupts masked, with gaps too short to dispatch one, and the
kernel's event queue holds them meanwhile. With room for two receptions
(the Kilobot's 48 bytes until the queue was sized for a crowd) about 1
frame in 80 was refused; with the template's pools none may be. Checks,
from every robot's counters at the end (--counters 0):
  no robot refused a frame (ir_refused, event_queue_full);
  every robot heard at least 40 frames a simulated 10 s;
  some robot's queue held three receptions at once (event_queue_peak of 57
  bytes or more: 19 each with the header), so the run had the bursts that
  two could not hold.
"""
import subprocess
import sys

from behaviour import Checks

RECEPTION_BYTES = 19  # kilobot_ir_rx (17) and the queue's 2-byte header


def main():
    sim, elf, world, seconds = sys.argv[1:5]
    done = subprocess.run([sim, "--world", world, "--time", seconds, "-q", "--no-progress", "--counters", "0", elf],
                          capture_output=True, text=True, timeout=240)
    if done.returncode != 0:
        sys.exit(f"openswarm-sim failed ({done.returncode}):\n{done.stderr}")
    robots = [dict(kv.split("=", 1) for kv in line.split()[1:])
              for line in done.stdout.splitlines() if line.startswith("counters ")]
    checks = Checks()
    checks.expect(len(robots) == 9, f"counters of 9 robots (found {len(robots)})")
    refused = {r["robot"]: (int(r["ir_refused"]), int(r["event_queue_full"])) for r in robots}
    checks.expect(all(a == 0 and b == 0 for a, b in refused.values()),
                  f"no frame refused (robot: ir_refused, event_queue_full): {refused}")
    least = 4 * float(seconds)
    heard = {r["robot"]: int(r["ir_received"]) for r in robots}
    checks.expect(all(n >= least for n in heard.values()), f"every robot heard at least {least:g} frames: {heard}")
    peak = max(int(r["event_queue_peak"]) for r in robots)
    checks.expect(peak >= 3 * RECEPTION_BYTES, f"a queue held three receptions at once (highest peak {peak} bytes)")
    checks.finish()


if __name__ == "__main__":
    main()
