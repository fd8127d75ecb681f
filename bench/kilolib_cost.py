#!/usr/bin/env python3
"""What classic Kilobot lab programs cost on OpenSwarm's kilolib (issue 15):
flash and RAM (avr-size: .text + .data, .data + .bss + .noinit) and the
main stack's worst use in the simulator, built with the kernel
configuration `openswarm build` gives a kilolib app, before (git REV, the
port's default pools: kilolib ran setup/loop and its transmitter in
threads) and now (kilolib_pools.h: the system thread alone). Writes the
table into docs/benchmarks.md between its markers.

    python3 bench/kilolib_cost.py --before 8205fc3 [--sim PATH] [--no-write]

The classic library's figures are the issue's measurements (5.8-6.4 KB of
flash, 110-132 B of RAM plus the main stack, avr-gcc -Os); the classic
library itself is not vendored here.
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
COMMAND = "python3 bench/kilolib_cost.py --before 8205fc3"
DOC = os.path.join(ROOT, "docs", "benchmarks.md")
BEGIN, END = "<!-- kilolib_cost.py: begin -->", "<!-- kilolib_cost.py: end -->"

# (name, source under the tree, what it does, simulator options to measure
# the main stack with: messaging programs run with neighbours)
PROGRAMS = [
    ("template", "templates/kilolib/main.c", "the kilolib template: blink blue, motors on", []),
    ("blink", "tests/avr/kilolib_blink.c", "blink red once a second", []),
    ("move", "tests/avr/kilolib_move.c", "the motion lab: straight, turns", []),
    ("hops", "tests/avr/kilolib_hops.c", "gradient: hop count from a seed robot", ["--robots", "4", "--line", "80", "--ir-range", "100"]),
    ("near", "tests/avr/kilolib_near.c", "messaging: distance to a neighbour", ["--robots", "2", "--distance", "40"]),
    ("ping", "tests/avr/kilolib_ping.c", "messaging with printf (debug.h)", ["--robots", "3", "--distance", "70"]),
    ("chorus", "tests/avr/kilolib_chorus.c", "everyone talks, printf (debug.h)", ["--robots", "3", "--distance", "70"]),
]

CMAKE = """cmake_minimum_required(VERSION 3.20)
project(kilolib_cost C CXX ASM)
include({root}/cmake/OpenSwarmKernel.cmake)
openswarm_add_kernel(kernel_app PORT kilobot CONFIG {config})
{sources}foreach(program {names})
  add_executable(${{program}} ${{SOURCE_${{program}}}})
  target_compile_options(${{program}} PRIVATE -std=gnu99)
  target_link_libraries(${{program}} PRIVATE kernel_app)
endforeach()
"""


def run(cmd, **kw):
    print("+", " ".join(cmd), file=sys.stderr)
    return subprocess.run(cmd, check=True, text=True, capture_output=True, **kw).stdout


def build(root, config, work):
    """The programs of root's tree against the kernel configured by config."""
    os.makedirs(work, exist_ok=True)
    sources = "".join("set(SOURCE_%s %s)\n" % (n, os.path.join(root, s)) for n, s, _, _ in PROGRAMS)
    with open(os.path.join(work, "CMakeLists.txt"), "w") as f:
        f.write(CMAKE.format(root=root, config=config, sources=sources,
                             names=" ".join(p[0] for p in PROGRAMS)))
    out = os.path.join(work, "build")
    run(["cmake", "-S", work, "-B", out, "-G", "Ninja", "-DCMAKE_BUILD_TYPE=MinSizeRel",
         "-DCMAKE_TOOLCHAIN_FILE=" + os.path.join(root, "ports/kilobot/cmake/avr-gcc.cmake")])
    run(["cmake", "--build", out, "-j2"])
    return out


def sizes(elf):
    sections = {}
    for line in run(["avr-size", "-A", elf]).splitlines():
        parts = line.split()
        if len(parts) >= 2 and parts[0].startswith(".") and parts[1].isdigit():
            sections[parts[0]] = int(parts[1])
    flash = sections.get(".text", 0) + sections.get(".data", 0)
    ram = sum(sections.get(s, 0) for s in (".data", ".bss", ".noinit"))
    return flash, ram


def main_stack(sim, elf, options):
    out = subprocess.run([sim, "--quiet", "--main-stack", "--time", "5"] + options + [elf],
                         text=True, capture_output=True).stderr
    used = [int(m) for m in re.findall(r"main stack: worst use (\d+) of", out)]
    return max(used) if used else None


def measure(root, config, work, sim):
    out = build(root, config, work)
    rows = {}
    for name, _, _, options in PROGRAMS:
        elf = os.path.join(out, name + ".elf")
        if not os.path.exists(elf):
            elf = os.path.join(out, name)
        rows[name] = sizes(elf) + (main_stack(sim, elf, options),)
    return rows


def table(before, after, rev):
    lines = [
        "| program | what it does | flash before | RAM before | flash now | RAM now | main stack now (before) |",
        "|---|---|---|---|---|---|---|",
    ]
    for name, source, what, _ in PROGRAMS:
        fb, rb, sb = before[name]
        fa, ra, sa = after[name]
        lines.append("| %s (`%s`) | %s | %d | %d | **%d** | **%d** | %s (%s) |" % (
            name, source, what, fb, rb, fa, ra, sa, sb))
    lines.append("| the classic library (the issue's measurements, not built here) | a lab program, "
                 "avr-gcc -Os | 5.8-6.4 KB | 110-132 + main stack | | | |")
    return "\n".join([
        BEGIN,
        "Bytes; flash is .text + .data, RAM .data + .bss + .noinit (every thread stack included;",
        "the main stack not, for either library). Before: git %s, the port's default pools" % rev,
        "(setup/loop and the transmitter in threads). Now: `kilolib_pools.h`, the system thread",
        "alone. Main stack: worst use in 5 simulated seconds (messaging programs with neighbours).",
        "Measured with `%s`." % COMMAND,
        "",
    ] + lines + [END])


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--before", default="8205fc3", help="git revision to measure as before")
    ap.add_argument("--sim", default=os.path.join(ROOT, "build", "sim", "openswarm-sim"))
    ap.add_argument("--no-write", action="store_true", help="print the table only")
    args = ap.parse_args()
    with tempfile.TemporaryDirectory(prefix="kilolib-cost-") as tmp:
        old = os.path.join(tmp, "before")
        os.makedirs(old)
        archive = subprocess.run(["git", "-C", ROOT, "archive", args.before], check=True,
                                 capture_output=True).stdout
        subprocess.run(["tar", "-x", "-C", old], input=archive, check=True)
        empty = os.path.join(tmp, "default_pools.h")
        open(empty, "w").write("/* the port's default pools, as openswarm build gave a kilolib app */\n")
        before = measure(old, empty, os.path.join(tmp, "before-build"), args.sim)
        pools = os.path.join(ROOT, "ports/kilobot/kilolib/include/kilolib_pools.h")
        after = measure(ROOT, pools, os.path.join(tmp, "after-build"), args.sim)
    text = table(before, after, args.before)
    print(text)
    if args.no_write:
        return
    doc = open(DOC).read()
    if BEGIN in doc:
        doc = doc[:doc.index(BEGIN)] + text + doc[doc.index(END) + len(END):]
    else:
        raise SystemExit("docs/benchmarks.md has no %s marker" % BEGIN)
    open(DOC, "w").write(doc)


if __name__ == "__main__":
    main()
