#!/usr/bin/env python3
"""Checks `openswarm size` and `openswarm build --json` of a built app against
what the app, the port and the kernel say, independently of the tool:

- each openswarm.json thread's stack as the kernel carves it (requested or the
  default, + PORT_STACK_EXTRA + the 4-byte guard, rounded up to whole
  OS_CFG_STACK_BLOCK_BYTES), and kilolib's threads when the app uses kilolib;
- the stack pool and the event data pool against the kernel's sizing rules,
  and that the pool and the thread slots hold every listed thread at once;
- each event's data (its type's size);
- equation (1)'s arithmetic, its n, m, d_i and stacks, its measured terms
  against docs/benchmarks.md, and that the gap to the reserved RAM is fully
  explained;
- the per-event cost against the link map (the event table's bytes per slot);
- the build's shares against size's owner table.

    check_footprint.py OPENSWARM_ROOT APP_DIR SIZE_LOG BUILD_JSON
"""
import json
import math
import os
import re
import sys

TYPE_BYTES = {"none": 0, "int8": 1, "uint8": 1, "int16": 2, "uint16": 2, "int32": 4, "uint32": 4}
GUARD = 4  # OS_STACK_GUARD_BYTES, kernel/src/kernel_internal.h (none without OS_CFG_STACK_CHECK)


def fail(message):
    sys.exit("check_footprint: " + message)


def defines(path):
    """#define NAME NUMBER of a C file."""
    found = {}
    for m in re.finditer(r"^#define\s+(\w+)\s+(\d+)u?\b", open(path).read(), re.M):
        found[m.group(1)] = int(m.group(2))
    return found


def round_up(n, block):
    return (n + block - 1) // block * block


def line_value(log, label):
    """The number at the end of the line that starts with label."""
    m = re.search(r"^  " + re.escape(label) + r" +(-?\d+)$", log, re.M)
    if not m:
        fail(f"no line '{label}' in the size output")
    return int(m.group(1))


def owner_table(log):
    table = {}
    for m in re.finditer(r"^  (\S.*?) +(\d+) +(\d+)$", log, re.M):
        table[m.group(1)] = (int(m.group(2)), int(m.group(3)))
    return table


def main():
    root, app, size_log, build_json = sys.argv[1:5]
    log = open(size_log).read()
    config = json.load(open(os.path.join(app, "openswarm.json")))
    port = config["port"]
    include = os.path.join(root, "ports", port, "include", "openswarm")
    cfg = defines(os.path.join(include, "port_config.h"))
    cfg.update(defines(os.path.join(app, "build", port, "openswarm", "openswarm_config.h")))
    extra = defines(os.path.join(include, "port_arch.h"))["PORT_STACK_EXTRA"]
    block = cfg["OS_CFG_STACK_BLOCK_BYTES"]

    # Threads: openswarm.json's (kilolib starts none: its program runs on
    # the system thread, so no stack line names it).
    threads = [(t["entry"], t.get("stack", 0) or cfg["OS_CFG_DEFAULT_STACK_BYTES"])
               for t in config.get("threads", [])]
    if "kilolib: " in log:
        fail("a kilolib thread is listed: kilolib starts none")
    stacks = 0
    for name, requested in threads:
        carved = round_up(requested + extra + (GUARD if cfg.get("OS_CFG_STACK_CHECK", 1) else 0), block)
        if not re.search(rf"^  {re.escape(name)} +{requested} -> +{carved}$", log, re.M):
            fail(f"expected the stack line '{name} {requested} -> {carved}'")
        stacks += carved
    shown = len(re.findall(r"^  .+ +\d+ -> +\d+$", log, re.M))
    if shown != len(threads):
        fail(f"{shown} stack lines, expected {len(threads)}")

    # The pools, as the kernel sizes them (config.h, kernel_internal.h).
    owners = owner_table(log)
    pool = round_up(cfg["OS_CFG_STACK_POOL_BYTES"] + (cfg["OS_CFG_MAX_THREADS"] - 1) * extra, block)
    if line_value(log, "the stack pool") != pool or owners.get("thread stacks (pool)", (0, 0))[1] != pool:  # no row: none
        fail(f"the stack pool should be {pool} bytes")
    if line_value(log, "not listed: spare, or threads the code starts") != pool - stacks:
        fail(f"the unlisted stack pool should be {pool - stacks} bytes")
    # Every listed thread starts: a slot and a stack each, at once.
    if stacks > pool:
        fail(f"the listed threads' stacks take {stacks} bytes, more than the {pool}-byte stack pool")
    if len(threads) + 1 > cfg["OS_CFG_MAX_THREADS"]:
        fail(f"{len(threads)} listed threads and the system thread need OS_CFG_MAX_THREADS >= "
             f"{len(threads) + 1}, found {cfg['OS_CFG_MAX_THREADS']}")
    arena = cfg["OS_CFG_EVENT_DATA_BYTES"]
    if line_value(log, "the event data pool") != arena or owners["event data (d_i)"][1] != arena:
        fail(f"the event data pool should be {arena} bytes")

    # Events' data.
    data = 0
    for e in config.get("events", []):
        size = e["size"] if "size" in e else TYPE_BYTES[e["type"]]
        if line_value(log, e["name"]) != size:
            fail(f"event {e['name']} should show {size} bytes")
        data += size

    # Equation (1).
    m = re.search(r"^Equation \(1\): RAM = C \+ (\d+) n \+ (\d+) m \+ sum d_i \+ sum stacks = "
                  r"(\d+) \+ (\d+)\*(\d+) \+ (\d+)\*(\d+) \+ (\d+) \+ (\d+) = (\d+) bytes$", log, re.M)
    if not m:
        fail("no equation (1) line")
    t, e, c, t2, n, e2, mm, d, s, total = map(int, m.groups())
    if (t, e) != (t2, e2) or n != len(threads) or mm != len(config.get("events", [])) or d != data or s != stacks:
        fail(f"equation (1) should have n={len(threads)}, m={len(config.get('events', []))}, "
             f"sum d_i={data}, sum stacks={stacks}")
    if total != c + t * n + e * mm + d + s:
        fail("equation (1) does not add up")
    # C and the per-item costs are the benchmark's measurements.
    bench = re.search(r"^ +(\d+) \+ (\d+) n \+ (\d+) m \+ sum\(d_i\)",
                      open(os.path.join(root, "docs", "benchmarks.md")).read(), re.M)
    if not bench or tuple(map(int, bench.groups())) != (c, t, e):
        fail(f"C + {t} n + {e} m with C = {c} disagrees with docs/benchmarks.md's equation; "
             "update costs_for in cli/src/ports.cpp after a benchmark run")
    # The per-event cost is the event table's bytes per slot in the link map.
    link_map = open(os.path.join(app, "build", port + "-size", "link.map")).read()
    # (a global without initialiser: listed among the common symbols)
    table = re.search(r"^os_events\s+0x([0-9a-f]+)\s", link_map, re.M)
    if not table or int(table.group(1), 16) != e * cfg["OS_CFG_MAX_EVENTS"]:
        fail(f"the event table is not {e} bytes per slot")

    # The RAM the build reserves, and the gap item by item.
    reserved = sum(owners.get(o, (0, 0))[1] for o in ("kernel and port", "thread stacks (pool)",
                                          "event data (d_i)", "event queue"))
    m = re.search(r"^The build reserves (\d+) bytes for the kernel .*?, (\d+) (more|fewer) than equation \(1\):$",
                  log, re.M | re.S)
    if not m or int(m.group(1)) != reserved:
        fail(f"the build reserves {reserved} bytes for the kernel")
    gap = int(m.group(2)) * (1 if m.group(3) == "more" else -1)
    if gap != reserved - total:
        fail(f"the gap should be {reserved - total}")
    items = [int(x) for x in re.findall(r"^  +(-?\d+)  \S", log[m.end():], re.M)]
    if sum(items) != gap:
        fail(f"the gap's items add up to {sum(items)}, not {gap}")

    # The build's shares: the same attribution as size's table.
    build = json.load(open(build_json))
    share = build["share"]
    kernel_flash, kernel_ram = owners["kernel and port"]
    flash_total = sum(f for f, r in owners.values())
    ram_total = sum(r for f, r in owners.values())
    if abs(share["kernel_and_port"]["flash_percent"] - 100 * kernel_flash / flash_total) > 0.06:
        fail("the build's kernel flash share disagrees with size's table")
    if abs(share["kernel_and_port"]["ram_percent"] - 100 * kernel_ram / ram_total) > 0.06:
        fail("the build's kernel RAM share disagrees with size's table")
    for what, whole in (("flash", build["flash"]), ("ram", build["ram"])):
        percents = sum(share[k][what + "_percent"] for k in ("kernel_and_port", "kernel_pools", "app", "c_runtime"))
        approx = sum(share[k][what + "_bytes_approx"] for k in ("kernel_and_port", "kernel_pools", "app", "c_runtime"))
        if not math.isclose(percents, 100, abs_tol=0.3) or abs(approx - whole) > 2:
            fail(f"the {what} shares add up to {percents}% and {approx} bytes, not 100% and {whole}")
    print("footprint checked: stacks " + ", ".join(f"{n} {r}" for n, r in threads) +
          f"; equation (1) {total} bytes, {reserved} reserved")


main()
