#!/usr/bin/env python3
"""Kilobot (ATmega328P) benchmarks: cycles from simavr's exact counter,
bytes from avr-size, simulator speed as a real-time factor. Writes
docs/benchmarks.md.

    python3 bench/avr_bench.py                 # builds into build-bench/
    python3 bench/avr_bench.py --baseline REV  # also the kernel of git REV, as "before"
    python3 bench/avr_bench.py --cycles        # only print the cycle table
"""
import argparse
import os
import re
import statistics
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BUILD = os.path.join(ROOT, "build-bench")
FW = os.path.join(BUILD, "avr")
FW_TESTS = os.path.join(BUILD, "avr-tests")
FW_NOLTO = os.path.join(BUILD, "avr-nolto")
SIM = os.path.join(BUILD, "host", "sim", "openswarm-sim")
F_CPU = 8_000_000
COMMAND = "python3 bench/avr_bench.py"
AVR_TOOLCHAIN = os.path.join(ROOT, "ports/kilobot/cmake/avr-gcc.cmake")


def run(cmd, **kw):
    print("+", " ".join(cmd), file=sys.stderr)
    return subprocess.run(cmd, check=True, text=True, capture_output=True, **kw).stdout


def build():
    run(["cmake", "-S", os.path.join(ROOT, "bench", "avr"), "-B", FW, "-G", "Ninja",
         "-DCMAKE_TOOLCHAIN_FILE=" + os.path.join(ROOT, "ports/kilobot/cmake/avr-gcc.cmake")])
    run(["cmake", "--build", FW])
    # The same firmware without link-time optimisation: its link map names
    # the source file of every function, so the flash can be attributed.
    run(["cmake", "-S", os.path.join(ROOT, "bench", "avr"), "-B", FW_NOLTO, "-G", "Ninja",
         "-DOPENSWARM_LTO=OFF",
         "-DCMAKE_TOOLCHAIN_FILE=" + os.path.join(ROOT, "ports/kilobot/cmake/avr-gcc.cmake")])
    run(["cmake", "--build", FW_NOLTO, "--target", "footprint_base"])
    # A typical messaging program: the kilolib test suite's ping.
    run(["cmake", "-S", os.path.join(ROOT, "tests", "avr"), "-B", FW_TESTS, "-G", "Ninja",
         "-DCMAKE_TOOLCHAIN_FILE=" + os.path.join(ROOT, "ports/kilobot/cmake/avr-gcc.cmake")])
    run(["cmake", "--build", FW_TESTS, "--target", "kilolib_ping", "kilolib_blink",
         "kilolib_blink_tickless"])


def build_cycles(root, build_dir):
    """The cycle firmware (this tree's bench/avr) against the kernel and
    port of `root`; its ELF."""
    run(["cmake", "-S", os.path.join(root, "bench", "avr"), "-B", build_dir, "-G", "Ninja",
         "-DCMAKE_TOOLCHAIN_FILE=" + AVR_TOOLCHAIN])
    run(["cmake", "--build", build_dir, "--target", "kernel_cycles", "kernel_cycles_minimal", "footprint_threads2",
         "bare"])
    return build_dir


def flash_two_threads(build_dir):
    """Kernel + port flash of the app with 2 user threads: its image minus
    the empty one."""
    app, bare = (sizes(os.path.join(build_dir, f"{e}.elf")) for e in ("footprint_threads2", "bare"))
    return (app[0] + app[1]) - (bare[0] + bare[1])


def build_baseline(rev):
    """The kernel, port and build files of git revision `rev`, with this
    tree's benchmark firmware: the same measurement of the older kernel."""
    src = os.path.join(BUILD, "baseline-src")
    subprocess.run(["rm", "-rf", src], check=True)
    os.makedirs(src)
    archive = subprocess.run(["git", "-C", ROOT, "archive", rev, "kernel", "ports", "cmake"],
                             check=True, capture_output=True).stdout
    subprocess.run(["tar", "-x", "-C", src], input=archive, check=True)
    subprocess.run(["cp", "-r", os.path.join(ROOT, "bench"), src], check=True)
    return build_cycles(src, os.path.join(BUILD, "baseline"))


def events(elf, *extra):
    out = run([SIM, "--marks", "--expect-stop", "--quiet", *extra, elf])
    evs = []
    for line in out.splitlines():
        kind, value, cycle = line.split()
        evs.append((kind, int(value), int(cycle)))
    return evs


def between(evs, starts, ends, threads=None):
    """Per-occurrence cycles from a mark in `starts` to the next mark in
    `ends` (of another thread than the start's, if `threads` maps marks to
    threads). Samples an interrupt fell into are left out and counted: the
    interrupt's own figures are measured on their own."""
    out, dropped, start, who, hit = [], 0, None, None, False
    for kind, value, cycle in evs:
        if kind == "irq":
            hit = True
            continue
        if start is not None and value in ends and (threads is None or threads[value] != who):
            if hit:
                dropped += 1
            else:
                out.append(cycle - start)
            start = None
        if value in starts:
            start, who, hit = cycle, threads[value] if threads else None, False
    return out, dropped


def after_irq(evs, vector, marks):
    """Cycles from each raise of `vector` to the next change to one of
    `marks`; left out (and counted) if another interrupt came between."""
    out, dropped, raised, hit = [], 0, None, False
    for kind, value, cycle in evs:
        if kind == "irq":
            if value == vector:
                raised, hit = cycle, False
            elif raised is not None:
                hit = True
        elif value in marks and raised is not None:
            if hit:
                dropped += 1
            else:
                out.append(cycle - raised)
            raised = None
    return out, dropped


def after_tick(evs, spinners):
    """The tick (vector 14) among spinning threads, each writing its two
    marks in turn (`spinners` maps mark to thread): cycles from the tick's
    raise to the next mark, split by whether that mark is another
    thread's (a preemption) or the interrupted one's (no switch)."""
    switched, stayed, dropped = [], [], 0
    raised, current, hit = None, None, False
    for kind, value, cycle in evs:
        if kind == "irq":
            if value == 14 and raised is None:
                raised = cycle
            elif raised is not None:
                hit = True
            continue
        if value not in spinners:
            current, raised = None, None  # another phase
            continue
        if raised is not None and current is not None:
            if hit:
                dropped += 1
            else:
                (switched if spinners[value] != current else stayed).append(cycle - raised)
        current, raised, hit = spinners[value], None, False
    return (switched, dropped), (stayed, 0)


def slice_ends(ticks, slice_ms=10):
    """A lone spinning thread's ticks (all of them returning to it), in
    order: those inside its slice, and every slice_ms-th, at its end. Both
    lists begin with its first tick, which includes the thread's start and
    which summary() leaves out. Which tick ends the first slice is found as
    the costliest of the slice_ms after it."""
    first = max(range(1, min(slice_ms + 1, len(ticks))), key=lambda i: ticks[i], default=1)
    ends = set(range(first, len(ticks), slice_ms))
    return ([t for i, t in enumerate(ticks) if i not in ends],
            ticks[:1] + [t for i, t in enumerate(ticks) if i in ends])


def summary(measured):
    """min, median, max, samples, left out. The first sample is left out
    too: it includes a thread's first start. The median is a sample (the
    lower middle one), not a mean of two."""
    samples, dropped = measured
    samples = samples[1:]
    return (min(samples), statistics.median_low(samples), max(samples), len(samples),
            dropped + 1)


def sizes(elf):
    """(.text, .data, .bss) from avr-size -A: its totals would count the
    .mmcu record, which the simulator reads and the robot never gets."""
    found = {}
    for line in run(["avr-size", "-A", elf]).splitlines():
        fields = line.split()
        if len(fields) >= 2 and fields[1].isdigit():
            found[fields[0]] = int(fields[1])
    return found.get(".text", 0), found.get(".data", 0), found.get(".bss", 0) + found.get(".noinit", 0)


def flash_by_file(map_path):
    """Bytes of code per source file, from a link map (.text input sections)."""
    text = open(map_path).read()
    text = text[text.index("Linker script and memory map"):]
    sizes = {}
    for m in re.finditer(r"^ \.text\S*\s+0x[0-9a-f]+\s+0x([0-9a-f]+)\s+(\S+)", text, re.M):
        size = int(m.group(1), 16)
        name = re.sub(r".*\((.*)\)", r"\1", m.group(2)).split("/")[-1]
        name = re.sub(r"\.obj$|\.o$", "", name)
        if size:
            sizes[name] = sizes.get(name, 0) + size
    return sizes


def profile(elf, seconds):
    """{function: cycles} from openswarm-sim --profile, '(asleep)' included."""
    result = subprocess.run([SIM, "--profile", "--quiet", "--time", str(seconds), elf],
                            check=True, text=True, capture_output=True)
    cycles = {}
    for line in result.stderr.splitlines():
        fields = line.split()
        if len(fields) == 3 and fields[0].isdigit():
            cycles[fields[2]] = int(fields[0])
    return cycles


def speed(elf, seconds, *extra):
    t0 = time.perf_counter()
    run([SIM, "--quiet", "--time", str(seconds), *extra, elf])
    return seconds / (time.perf_counter() - t0)


# Counted from `avr-objdump -d build-bench/avr/kernel_cycles.elf` (AVR
# instruction timings): static facts of the code, not measurements.
WHERE_THE_CYCLES_GO = """### Where the cycles go, and which targets are not met

Five changes made the kernel faster without changing what it does (each commit gives its
measured effect): the end of an interrupt decides again only if something a decision reads
has changed (`os.reconsider`: a thread made ready, a priority or the policy changed, an event
sent, a thread ended, a stop, the end of a slice), so the tick in the middle of a slice runs
no decision; the tick checks the running thread's stack guard only when it leads to a
decision (at least once a slice) instead of every millisecond; most ticks are quiet
(`os_tick_quiet`, `system_time.c`): a countdown (`os.quiet_ticks`) says how many of the coming
ticks need no look at the deadlines, the handler watch or the clock event, so a tick that
does not end the slice counts the time and the slice and returns from the interrupt
without `os_isr_enter` and `os_isr_exit`; the tick that ends a slice takes that way too when
its decision is a plain rotation (`tick_ending_slice`: a user thread outside critical
sections and nested interrupts, its guard intact, no work for the system thread, someone
ready), rotating as `Sys_Yield` does instead of taking the general tick and decision; and
round robin queues a thread in constant time (`scheduler.c`: the ready list keeps its last
thread, and a yield or a slice's end rotates in one step), where its policy's `insert`
walked the list. The first two took the tick with no switch from 303 cycles to 178, the
third to 101 (102 now: the test for the slice's end); the last two took the tick that
switches from 495 to 348 (4 threads: 523 to 357) and `Sys_Yield` from 282 to 246 (4
threads: 308 to 257), now the same however many threads are ready. They cost about 10
cycles on each insert under another policy (the priority policy's woken thread: 894 before
them, 914 after), 2 to 4 on the paths that start handlers, and flash (below). Three smaller
ones followed: the dispatch's scan for waiters ends at the last thread that waits for an
event instead of the last slot (the woken thread 751 to 700, 914 to 863); a handler with
neither condition nor context is called without the dispatch loop saving registers for it
(interrupt to handler 310 to 301, round trip 439 to 421; kilolib's programs keep the one
call, as the second costs 30 bytes their budget has not); and `Sys_Yield` and the slice's
end test the interrupt and critical-section depths at once (4 cycles each). Going without
the optional features meets no other target (their column: 0 to 53 cycles a path, the
most on the send and its round trip); what the cycles are spent on, counted from the
disassembly (`avr-objdump -d`):

- **Any interrupt** that may call the kernel is a C handler that calls functions, so avr-gcc
  saves and restores the 12 call-clobbered registers, r0, r1 and SREG: with the interrupt's
  entry (4 cycles), the vector's jump (3) and `reti` (4), about 70 cycles before the kernel
  does anything. A thread switch from an interrupt then saves the 18 callee-saved registers in
  `port_switch` (100 cycles thread to thread, the first row): all 32 registers and SREG
  change hands, as in FreeRTOS's port, which saves them in one place.
- **Tick with no switch (102, target 150: met):** besides those 70, the quiet countdown's
  test and decrement (7), the test for the slice's end (1 more than before it went out of line), the slice's test and count (16: every tick counts it, so a slice
  ends on its tick whatever the countdown says), the time's lowest byte (6: the other three
  take the carry once in 256 ticks, out of line) and the jump out (2). The tick's interrupt
  still saves every call-clobbered register: the ticks that are not quiet call the kernel,
  and avr-gcc saves them at the interrupt's entry either way. A tick that is not quiet (the
  end of a slice, or the countdown run out: at the nearest deadline, every tick while
  handlers run or the clock event has a listener, and at least every 256 ticks) does what
  every tick did before, in `os_tick`, less the deadlines, the handler watch and the clock
  event when only the slice ended.
- **Sys_Yield (242, target 200):** `port_switch` is 100 of it; the kernel's part (142) is
  the call and its register saves (23), the checks the call promises (in a thread, not in
  an interrupt or a critical section, else `SYS_E_CONTEXT`: 13), interrupts masked (2),
  someone ready and no work for the system thread (16), the stack guard (22), the policy's
  test (7: it is replaceable at run time), round robin's rotation with a fresh slice (31),
  the two threads' states (6), the switch count (11, `Sys_Get_Stats`) and the running
  thread's change (6). Without the optional features (no guard) it is 221; 200 would also
  take the switch count and the context checks away: what the API reports, not speed.
  FreeRTOS takes 251-258 here, ChibiOS 220.
- **Tick to another thread (340, target 300):** 179 of it is fixed: the interrupt's entry
  and exit with its 15 saved registers (79) and `port_switch` (100). The kernel's 161 (167
  when it was counted, less the 6 of a slice store the rotation makes anyway): the
  quiet test that finds the slice's end and the out-of-line call (14), that call's register
  saves and return (17), the checks that make the decision a plain rotation (33) and the
  stack guard every slice's end checks (20), the tick's count (the time, the countdown,
  the slice: 19), and the rotation as in `Sys_Yield` (68, the switch count's 11 in it).
  Without the optional features it is 324. 300 leaves the kernel 121 cycles, less than the
  count, the rotation and the checks that tell it is plain (125 without the guard and the
  switch count): meeting it would take skipping those checks, which keep every slice's end
  exact (an event queued, a thread ended, a critical section: the general decision).
- **Tick at the end of a lone thread's slice (187, target 150 for a tick with no switch):**
  one tick in ten of a thread that spins while no other is ready. It took the general way
  (331: the interrupt's entry and exit, `os_tick`, the decision that renews the slice)
  until the slice's end took the quiet way for it too (`os_slice_over`: a fresh slice
  instead of a rotation). Over the quiet tick's 102 it spends about what the tick to another
  thread spends before its rotation: the out-of-line call with its saves (31), the checks
  that make the decision plain (33) and the stack guard (20), which must
  stay: a thread that overflows while it spins alone is stopped within its slice
  (`Faults.AnOverflowingThreadThatSpinsAloneIsStoppedWithinASlice`, and the firmware
  suite's `spin_fault`). Averaged over its ticks it is about 110.
- **Interrupt to a woken thread (684, target 350):** measured step by step with 8 markers
  in a scratch build (the CPU idle: 717 with the markers, about 4 cycles each): the
  interrupt's entry, `Sys_Send_Event`'s checks and the occurrence held (103), the
  interrupt's end (13), back into the system thread's loop from its sleep (102), the
  dispatch's entry, its pop and its scan to the waiter (97), the waiter's wake - its data
  copied, its wait left, made ready through the policy - and the rest of the scan (127),
  the handler table's look (23), the dispatch's end and the way to the decision (57), the
  decision (71), and the switch with the waiter's return through its wait's calls (124).
  With a lower-priority thread spinning (847) the interrupt's end decides on the
  spinning thread's stack and dispatches on the system stack; the priority policy's
  queueing (an indirect call and a walk of the ready list) takes the wake to 165 and the
  decision after the dispatch to 263. The semantics cost most of it: waiters and handlers
  of one occurrence are served in one dispatch, in order, on the system thread, never in
  the interrupt; any number of threads may wait for one event, each woken with its own
  copy; the policy is replaceable at run time. Waking the waiters in the send instead,
  when nothing needs the system thread (no handler, no waiter's condition, nothing queued
  before it), was tried twice and measured **slower** both times: with scans to tell
  whether it may (870 cycles, when this row was 770),
  and with tests in constant time - a bit per event for its handlers, a count of the
  waiters with a condition - (731 with the CPU idle, 872 with a thread spinning, and 56
  more on the paths to a handler, 126 bytes more flash). The
  wake costs the same wherever it runs; with the CPU idle the system thread dispatches at
  once anyway, and the test and the send's own call (no longer inlined into the
  interrupt) come on top. Of 350, the interrupt's entry and exit and the switch take
  about 195, which would leave the kernel 155 for the send, finding and waking the waiter
  and the decision: they take about 490 now.
- **Interrupt to handler (301, target 250):** measured step by step with markers in a
  scratch build (a thread spinning; 10 markers took it to 354, about 5 cycles each, in the
  figures): the interrupt's entry with its saved registers, the benchmark's own interrupt
  code and the call to send (69), `Sys_Send_Event`'s checks (id, registration, size) and
  the occurrence held in its event's kept data (45), back to the end of the interrupt
  (30), to the decision (26), the decision's look (running, no critical section, something
  queued) and the way onto the system thread's stack with the dispatch's register saves
  (68), the pop (47), the waiters' test (5: none wait), the handler table's scan to the
  subscription and its condition's and context's tests, the handler watch set, interrupts
  enabled (43) and the call into the handler (21). With the CPU idle the system thread's
  own loop dispatches instead of an interrupted thread's decision (313). Without the
  optional features it is 289. 250 would need handlers run in the interrupt, on the
  interrupted thread's stack: the design runs every handler on the system thread, after
  the interrupt and in order with the waiters, so that a handler may send, start threads
  and take as long as it needs with interrupts enabled, on a stack of its own.
- **Send round trip (421, target 350):** the same steps from a thread (14 markers: 486):
  the call and its checks (25), the occurrence held with its 2 bytes (63), to the decision
  through the stack guard's check (68), onto the system stack (68), the pop (47), the
  waiters' test (5), the scan and the call (63), the handler itself (8), the dispatch's end
  and the way back from the system stack with its register restores (61), the decision
  after it (11: nothing to switch to) and the way back to the thread through the calls
  (67). Without the optional features it is 378. FreeRTOS's nearest, a message to a task
  and its answer, is two task switches: 1000 cycles in the issue's reference table.
- **Flash (target 2560 bytes for the app with 2 user threads):** not met, and further from
  it than before the tick's and round robin's shortcuts: the quiet tick's two ways through
  the tick and the slice's end with its rotation out of line cost about 520 bytes together
  (the Footprint section's row without them: `OS_CFG_QUIET_TICK 0`, at the tick's 180
  cycles and the general decision's 495), round robin's constant-time queueing about 110
  and 1 byte of RAM (its last thread's pointer, 2 bytes, less the one byte the system
  thread's reap and stop flags now share). Without the quiet tick and the optional
  features as well, the app with 2 user threads is still the Footprint section's smallest
  row, over 3 KB: threads with a stack pool and its guard, events with kept data, waits
  with conditions and timeouts, handlers on the system thread, a replaceable policy and
  faults reported. Going under 2560 would take nearly a fifth of that core away, which no
  setting does; the Footprint section shows where the code goes by source file.

"""


def cycle_rows(evs):
    """(what, from, to, (min, median, max, samples, left out), target) per
    figure of kernel_cycles.c (its header lists the markers)."""
    def threads(marks, per_thread=1):
        return {m: (m - marks[0]) // per_thread for m in marks}

    yield2, yield4 = threads(range(20, 22)), threads(range(22, 26))
    spin2, spin4 = threads(range(30, 34), 2), threads(range(34, 42), 2)
    (tick2, tick2_stay), (tick4, tick4_stay) = after_tick(evs, spin2), after_tick(evs, spin4)
    lone_quiet, lone_slice_end = slice_ends(after_tick(evs, {70: 0, 71: 0})[1][0])
    irq = "simavr raises the interrupt (its flag is set)"
    return [
        ("port_switch, thread to thread (assembly, no kernel)",
         "`out GPIOR2` before the call", "the other thread's `out GPIOR2` after its return",
         summary(between(evs, {10, 11}, {10, 11}, {10: 0, 11: 1})), ""),
        ("Sys_Yield, thread to thread, 2 threads, 2 call sites",
         "`out GPIOR2` before the call", "the next thread's `out GPIOR2` after its call returns",
         summary(between(evs, set(yield2), set(yield2), yield2)), "<= 200"),
        ("Sys_Yield, thread to thread, 4 threads, 2 call sites",
         "`out GPIOR2` before the call", "the next thread's `out GPIOR2` after its call returns",
         summary(between(evs, set(yield4), set(yield4), yield4)), "<= 200"),
        ("tick interrupt to another thread, 2 threads spinning", irq,
         "the other thread's first `out GPIOR2`", summary(tick2), "<= 300"),
        ("tick interrupt to another thread, 4 threads spinning", irq,
         "the next thread's first `out GPIOR2`", summary(tick4), "<= 300"),
        ("tick with no switch, 2 threads spinning", irq,
         "the interrupted thread's next `out GPIOR2`", summary(tick2_stay), "<= 150"),
        ("tick with no switch, 4 threads spinning", irq,
         "the interrupted thread's next `out GPIOR2`", summary(tick4_stay), "<= 150"),
        ("tick with no switch, 1 thread spinning, inside its slice", irq,
         "its next `out GPIOR2`", summary((lone_quiet, 0)), "<= 150"),
        ("tick with no switch, 1 thread spinning, at its slice's end (a fresh one: nobody else is ready)",
         irq, "its next `out GPIOR2`", summary((lone_slice_end, 0)), "<= 150"),
        ("interrupt to event handler, a thread spinning", irq,
         "the handler's first `out GPIOR2`", summary(after_irq(evs, 7, {44})), "<= 250"),
        ("interrupt to event handler, the CPU idle", irq,
         "the handler's first `out GPIOR2`", summary(after_irq(evs, 7, {45})), "<= 250"),
        ("interrupt to woken thread, the CPU idle", irq,
         "the woken thread's first `out GPIOR2`", summary(after_irq(evs, 7, {50})), "<= 350"),
        ("interrupt to woken thread, a lower-priority thread spinning", irq,
         "the woken thread's first `out GPIOR2`", summary(after_irq(evs, 7, {51})), "<= 350"),
        ("event send from a thread to its handler", "`out GPIOR2` before `Sys_Send_Event`",
         "the handler's first `out GPIOR2`", summary(between(evs, {60}, {61})), ""),
        ("event send from a thread to its handler and back", "`out GPIOR2` before `Sys_Send_Event`",
         "the thread's `out GPIOR2` after it returns", summary(between(evs, {60}, {62})), "<= 350"),
    ]


def measure_cycles(build_dir, firmware="kernel_cycles"):
    elf = os.path.join(build_dir, firmware + ".elf")
    return cycle_rows(events(elf, "--watch-irq", "14", "--watch-irq", "7"))


def cycle_table(rows, minimal, before, rev):
    """The cycle rows; `minimal` the same measured without the optional
    features (its median, min-max), `before` those of git `rev`."""
    out = ["| what | from | to | min | median | max | samples (left out) | optional features off: median (min-max) |"
           + (f" before ({rev}): median (min-max) |" if before else "") + " target |",
           "|---|---|---|---:|---:|---:|---:|---:|" + ("---:|" if before else "") + "---|"]
    for i, (name, start, end, (lo, med, hi, n, left), target) in enumerate(rows):
        m = minimal[i][3]
        old = ""
        if before:
            b = before[i][3]
            old = f" {b[1]} ({b[0]}-{b[2]}) |"
        out.append(f"| {name} | {start} | {end} | {lo} | {med} | {hi} | {n} ({left}) | {m[1]} ({m[0]}-{m[2]}) |"
                   f"{old} {target} |")
    return out


# The page as it was: other commands' sections are kept as they last wrote
# them (bench/kilolib_cost.py's, with its heading, after the footprint;
# bench/world_bench.py's and bench/qemu_bench.py's at the end).
PAGE = os.path.join(ROOT, "docs", "benchmarks.md")
with open(PAGE) as _page:
    KEPT = _page.read()
_KILOLIB_FROM, _KILOLIB_TO = "## Classic kilolib programs", "<!-- kilolib_cost.py: end -->"
KILOLIB_COST = (KEPT[KEPT.index(_KILOLIB_FROM):KEPT.index(_KILOLIB_TO) + len(_KILOLIB_TO)] + "\n"
                if _KILOLIB_FROM in KEPT and _KILOLIB_TO in KEPT else "")


def main():
    parser = argparse.ArgumentParser(description="Kilobot kernel benchmarks (writes docs/benchmarks.md)")
    parser.add_argument("--baseline", metavar="REV",
                        help="also measure the kernel of git revision REV, shown as 'before'")
    parser.add_argument("--cycles", action="store_true",
                        help="only build and measure the cycle firmware; print its table")
    args = parser.parse_args()
    # The simulator first: the baseline's firmware is measured with it too.
    run(["cmake", "-S", ROOT, "-B", os.path.join(BUILD, "host"), "-G", "Ninja",
         "-DOPENSWARM_TESTS=OFF", "-DCMAKE_BUILD_TYPE=Release"])
    run(["cmake", "--build", os.path.join(BUILD, "host"), "--target", "openswarm-sim"])
    before, flash_before = None, None
    if args.baseline:
        baseline = build_baseline(args.baseline)
        before, flash_before = measure_cycles(baseline), flash_two_threads(baseline)
    if args.cycles:
        now = build_cycles(ROOT, FW)
        print("\n".join(cycle_table(measure_cycles(now), measure_cycles(now, "kernel_cycles_minimal"), before,
                                     args.baseline)))
        print(f"kernel + port flash, app with 2 user threads: {flash_two_threads(now)} bytes"
              + (f" (before: {flash_before})" if flash_before else ""))
        return
    build()
    rows = measure_cycles(FW)
    fp = {v: sizes(os.path.join(FW, f"footprint_{v}.elf"))
          for v in ("base", "plus_thread", "plus_event", "minimal", "tickless", "threads2", "threads4",
                    "threads2_loud", "threads2_minimal")}
    # With link-time optimisation symbols merge across files, so the kernel's
    # share is measured as a difference from an image without it.
    bare = sizes(os.path.join(FW, "bare.elf"))
    per_thread = (fp["plus_thread"][1] + fp["plus_thread"][2]) - (fp["base"][1] + fp["base"][2])
    per_event = (fp["plus_event"][1] + fp["plus_event"][2]) - (fp["base"][1] + fp["base"][2])
    with open(os.path.join(ROOT, "bench", "avr", "footprint_base.h")) as f:
        pool = int([l for l in f if "STACK_POOL_BYTES" in l][0].split()[2])
    frame = 64  # PORT_STACK_EXTRA, reserved in the pool for each user thread slot
    def code(v):
        """Kernel + port flash of footprint_<v>: its image minus the empty one."""
        return (fp[v][0] + fp[v][1]) - (bare[0] + bare[1])

    rom, rom_minimal = code("base"), code("minimal")
    tickless_rom = (fp["tickless"][0] + fp["tickless"][1]) - (fp["base"][0] + fp["base"][1])
    tickless_ram = (fp["tickless"][1] + fp["tickless"][2]) - (fp["base"][1] + fp["base"][2])
    ram = (fp["base"][1] + fp["base"][2]) - (bare[1] + bare[2]) - pool - frame
    idle_rtf = speed(os.path.join(FW, "footprint_base.elf"), 60)
    ping = os.path.join(FW_TESTS, "kilolib_ping.elf")
    ping_rtf = {n: speed(ping, 20, "--robots", str(n), "--distance", "60") for n in (1, 2, 10)}

    out = []
    out.append("# Benchmarks\n")
    out.append("Measured by `%s` on the ATmega328P at 8 MHz (Kilobot port), from\n"
               "simavr 1.6's exact cycle counter (`openswarm-sim --marks --watch-irq`), avr-size\n"
               "and avr-nm. Firmware: `bench/avr/`. Built with avr-gcc -Os -flto.\n" % COMMAND)
    out.append("## Cycles\n")
    out.append("Firmware `bench/avr/kernel_cycles.c` (its header lists the phases), kernel configured\n"
               "with 6 thread slots (`bench/avr/cycles_config.h`: the system thread, up to 4 user\n"
               "threads and a control thread that sleeps and ends each phase). Every figure is a set\n"
               "of per-occurrence samples, from the instruction in the `from` column to the one in\n"
               "the `to` column; the marker writes (`out GPIOR2`, 1 cycle) are included. Interrupt\n"
               "figures start when simavr raises the interrupt: the CPU first finishes its\n"
               "instruction and spends 4 cycles entering the vector. A sample another interrupt fell\n"
               "into (a tick during a yield) is left out and counted, as is the first of each\n"
               "figure (a thread's first start). `Sys_Yield` is called from two functions, so link-time\n"
               "optimisation cannot fold it into its caller. Medians are samples (the lower middle\n"
               "one), never means. The column of the optional features off measures the same\n"
               "firmware against `bench/avr/cycles_minimal_config.h` (`OS_CFG_STACK_CHECK 0`,\n"
               "`OS_CFG_CLOCK_EVENT 0`, `OS_CFG_HANDLER_LIMIT_MS 0`, `OS_CFG_HANDLER_CONTEXT 0`):\n"
               "what a robot gains on each path by going without them.\n")
    out.extend(cycle_table(rows, measure_cycles(FW, "kernel_cycles_minimal"), before, args.baseline))
    out.append("")
    out.append(WHERE_THE_CYCLES_GO)
    out.append("## Footprint\n")
    out.append("Minimal app (`bench/avr/footprint_app.c`: one thread that sleeps) with the smallest\n"
               "kernel configuration (`bench/avr/footprint_base.h`: 2 thread slots, 6 event slots\n"
               "(the kernel's 2 and 4 more; the app uses none of the port's devices), 1 subscription,\n"
               "a 16-byte queue).\n")
    out.append("| what | bytes | target |")
    out.append("|---|---:|---|")
    out.append(f"| whole image: flash (text + data) | {fp['base'][0] + fp['base'][1]} | |")
    out.append(f"| whole image: RAM (data + bss) | {fp['base'][1] + fp['base'][2]} | |")
    out.append(f"| empty image (`bench/avr/bare.c`: C runtime and vectors) | {bare[0] + bare[1]} | |")
    out.append(f"| kernel + port code, app with 1 user thread (image minus the empty one; includes the app's few calls) | {rom} | |")
    for n in (2, 4):
        was = f" (before, at {args.baseline}: {flash_before})" if n == 2 and flash_before else ""
        out.append(f"| the same, app with {n} user threads (`footprint_threads{n}.h`) | {code(f'threads{n}')}{was} | "
                   f"{'<= 2560' if n == 2 else ''} |")
    out.append(f"| the same, app with 2 user threads, without the quiet tick "
               f"(`footprint_threads2_loud.h`: `OS_CFG_QUIET_TICK 0`) | {code('threads2_loud')} | |")
    out.append(f"| the same, app with 2 user threads, without the quiet tick and the optional features "
               f"(`footprint_threads2_minimal.h`) | {code('threads2_minimal')} | |")
    out.append(f"| the same without the optional features (`bench/avr/footprint_minimal.h`: "
               f"`OS_CFG_STACK_CHECK 0`, `OS_CFG_CLOCK_EVENT 0`, `OS_CFG_HANDLER_LIMIT_MS 0`, `OS_CFG_HANDLER_CONTEXT 0`), 1 user thread | {rom_minimal} | |")
    out.append(f"| kernel + port RAM with one thread slot (stack pool and frame excluded) | {ram} | <= 200 |")
    out.append(f"| per extra thread slot: its control block (the pool also grows by its {frame}-byte frame) | {per_thread - frame} | <= 12 |")
    out.append(f"| per extra event slot (data excluded) | {per_event} | <= 4 |\n")
    tcb = per_thread - frame
    fixed = ram - tcb * 2 - per_event * 6  # footprint_base has 2 thread and 6 event slots
    out.append(f"So the kernel's RAM for n user threads and m application events (the system\n"
               f"thread and the base configuration's 6 event slots in the constant) is about\n\n"
               f"    {fixed + tcb + per_event * 6} + {tcb} n + {per_event} m + sum(d_i) + sum(stack_i + {frame})\n\n"
               f"against the paper's 1142 + 146 n + 6 m + sum(d_i) on the dsPIC, whose 146 B per thread\n"
               f"include a 128-byte stack. The main stack (interrupts, handlers, the system thread)\n"
               f"comes on top of both.\n")
    by_file = flash_by_file(os.path.join(FW_NOLTO, "footprint_base.map"))
    port_files = [f for f in by_file if f in ("port.c", "switch.S", "motors.c")]
    kernel_files = [f for f in by_file if f not in port_files and f.endswith(".c")
                    and f != "footprint_app.c"]
    kernel_bytes = sum(by_file[f] for f in kernel_files)
    port_bytes = sum(by_file[f] for f in port_files)
    out.append("Where the code goes: the same minimal image built without link-time optimisation,\n"
               "whose link map names each function's source file (LTO then shrinks the whole by\n"
               f"about {100 - 100 * rom // max(1, kernel_bytes + port_bytes)}%, so the shares are what matter):\n")
    out.append("| source | bytes |")
    out.append("|---|---:|")
    for f in sorted(kernel_files + port_files, key=lambda f: -by_file[f]):
        out.append(f"| {'port: ' if f in port_files else ''}`{f}` | {by_file[f]} |")
    out.append(f"| kernel total / port total | {kernel_bytes} / {port_bytes} |\n")
    # The tick's interrupt and the kernel and port functions it calls (which
    # of them stand alone depends on what link-time optimisation inlined);
    # with tickless idle, the alarm's interrupt and the wake-up's count.
    tick_functions = ("__vector_14", "kilobot_tick", "os_tick", "count_slice_and_check_guard",
                      "os_check_timeouts", "carry_time", "os_isr_exit")
    alarm_functions = ("__vector_11", "port_tickless_wake", "kilobot_tickless_stop", "os_ticks_slept")
    seconds = 2
    at_rest = {}
    for variant in ("kilolib_blink", "kilolib_blink_tickless"):
        cycles = profile(os.path.join(FW_TESTS, variant + ".elf"), seconds)
        total = sum(cycles.values())
        asleep = cycles.get("(asleep)", 0)
        tick = sum(v for k, v in cycles.items() if k.split(".")[0] in tick_functions)
        alarm = sum(v for k, v in cycles.items() if k.split(".")[0] in alarm_functions)
        at_rest[variant] = (100 * asleep / total, 100 * tick / total, 100 * alarm / total,
                            100 * (total - asleep - tick - alarm) / total)
    out.append(KILOLIB_COST)
    out.append("## The kernel at rest\n")
    out.append(f"`tests/avr/kilolib_blink.c` (a classic kilolib program that blinks) for {seconds} simulated\n"
               "seconds, start-up included, under `openswarm-sim --profile`, with the periodic 1 ms tick\n"
               "(the default) and with tickless idle (`OS_CFG_TICKLESS 1`: `kilolib_blink_tickless`):\n")
    out.append("| where the cycles go | periodic tick | tickless idle |")
    out.append("|---|---:|---:|")
    p_, t_ = at_rest["kilolib_blink"], at_rest["kilolib_blink_tickless"]
    out.append(f"| asleep (the idle thread's SLEEP) | {p_[0]:.1f}% | {t_[0]:.1f}% |")
    out.append(f"| the 1 ms tick ({', '.join(f'`{f}`' for f in tick_functions)}) | {p_[1]:.1f}% | {t_[1]:.1f}% |")
    out.append(f"| tickless idle's alarms and wake-ups ({', '.join(f'`{f}`' for f in alarm_functions)}) | {p_[2]:.1f}% | {t_[2]:.1f}% |")
    out.append(f"| everything else | {p_[3]:.1f}% | {t_[3]:.1f}% |\n")
    out.append("## Tickless idle\n")
    out.append(f"With `OS_CFG_TICKLESS 1` (off by default, for its flash: see architecture.md) `kilolib_blink` is asleep "
               f"{t_[0]:.1f}% of its first {seconds} s (target: >= 99%), against {p_[0]:.1f}% with the periodic tick "
               f"(the table above). It wakes for its own `delay()`s and for the alarms that chain a "
               f"sleep across Timer1's 8.192 ms wrap (one every 7 ms, about 130 cycles each), and for "
               f"kilolib's transmitter, a handler the kilo tick calls on. Cost: {tickless_rom} bytes of flash and "
               f"{tickless_ram} of RAM (`bench/avr/footprint_tickless.h` against `footprint_base`); a thread "
               f"woken at a deadline runs about 290 cycles later than the tick's own interrupt would have "
               f"woken it; an interrupt that ends a sleep first credits the ticks slept "
               f"(`port_tickless_wake`), about 110 cycles more from an interrupt to the thread it wakes "
               f"(813 against 704 without it, measured once with the earlier cycles firmware built with it, before the changes measured above). How it works: "
               f"[architecture.md](architecture.md#tickless-idle).\n")
    out.append("## Against the reference numbers (`../shared/design.md`)\n")
    out.append("| what | OpenSwarm (this page) | reference |")
    out.append("|---|---|---|")
    median = {r[0]: r[3][1] for r in rows}  # by the row's name: rows come and go
    out.append(f"| voluntary switch | port_switch {median['port_switch, thread to thread (assembly, no kernel)']}, "
               f"Sys_Yield {median['Sys_Yield, thread to thread, 2 threads, 2 call sites']} cycles (2 threads) | "
               "FreeRTOS yield about 259; ChibiOS/RT about 180; RIOT about 355 |")
    out.append(f"| interrupt to a thread | {median['interrupt to woken thread, the CPU idle']} cycles (to a handler: "
               f"{median['interrupt to event handler, the CPU idle']}) | FreeRTOS about 603 |")
    out.append(f"| kernel code | {rom} B (kernel + port, minimal app; {rom_minimal} B without the optional features) | FreeRTOS 2.3 KB (2 tasks); RIOT 2.2 KB; QP-nano about 2.4 KB |")
    out.append(f"| RAM per thread | {tcb} B + stack | FreeRTOS 34 B per TCB; ChibiOS 31 B per thread; paper 146 B (with a 128 B stack) |\n")
    out.append("## Simulator speed\n")
    out.append("| firmware | real-time factor |")
    out.append("|---|---:|")
    out.append(f"| mostly idle (the footprint app, 60 simulated s; the CPU sleeps) | {idle_rtf:.0f}x |")
    for n, rtf in ping_rtf.items():
        out.append(f"| messaging (`tests/avr/kilolib_ping.c`, a classic kilolib program: robot 1 sends "
                   f"twice a second, the others receive; its empty loop() keeps the CPU busy), {n} robot{'s' if n > 1 else ''}, 20 s | {rtf:.1f}x |")
    out.append("")
    out.append("Real-time factor = simulated seconds per wall-clock second on one core of the\n"
               "machine that ran the command; it varies with the machine.\n")
    # bench/world_bench.py's section stays as it last wrote it.
    world = KEPT[KEPT.index("<!-- world_bench: begin -->"):] if "<!-- world_bench: begin -->" in KEPT else ""
    with open(PAGE, "w") as f:
        f.write("\n".join(out) + ("\n" + world if world else ""))
    print("\n".join(out))


if __name__ == "__main__":
    main()
