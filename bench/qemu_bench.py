#!/usr/bin/env python3
"""Kernel costs on the e-puck2's Cortex-M4 under QEMU: instruction counts of
a switch, a yield, a preemption by the tick, an interrupt to a handler and
to a woken thread (QEMU counts instructions, not cycles), and the image's
flash and RAM with the terms of the paper's equation (1). Rewrites its
section of docs/benchmarks.md.

    python3 bench/qemu_bench.py          # builds into build-bench/qemu
"""
import os
import re
import statistics
import subprocess
import sys
from collections import defaultdict

sys.dont_write_bytecode = True  # no bench/__pycache__ in the source tree
import benchmarks_page  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BUILD = os.path.join(ROOT, "build-bench", "qemu")
BUILD_NOLTO = os.path.join(ROOT, "build-bench", "qemu-nolto")  # link maps that name files
COMMAND = "python3 bench/qemu_bench.py"
BEGIN, END = "<!-- qemu_bench: begin -->", "<!-- qemu_bench: end -->"
STACK_EXTRA = 384  # PORT_STACK_EXTRA (ports/cortex_m4/include/openswarm/port_arch.h)


def run(cmd, **kw):
    return subprocess.run(cmd, check=True, text=True, capture_output=True, **kw).stdout


def build():
    for folder, lto in ((BUILD, "ON"), (BUILD_NOLTO, "OFF")):
        run(["cmake", "-S", os.path.join(ROOT, "bench", "qemu"), "-B", folder, "-G", "Ninja",
             "-DCMAKE_TOOLCHAIN_FILE=" + os.path.join(ROOT, "ports", "cortex_m4", "cmake", "arm-none-eabi.cmake"),
             "-DCMAKE_BUILD_TYPE=MinSizeRel", "-DOPENSWARM_LTO=" + lto])
        run(["cmake", "--build", folder])


def samples():
    """Every sample the firmware prints, by kind. -icount shift=0: one
    instruction is one nanosecond of virtual time, which TIM2 counts."""
    out = run(["qemu-system-arm", "-M", "netduinoplus2", "-display", "none", "-monitor", "none",
               "-serial", "stdio", "-semihosting-config", "enable=on,target=native",
               "-icount", "shift=0,align=off,sleep=off",
               "-kernel", os.path.join(BUILD, "kernel_instructions.elf")], timeout=120)
    found = defaultdict(list)
    for line in out.splitlines():
        what, _, count = line.partition(" ")
        if count.isdigit():
            found[what].append(int(count))
    return found


def symbol_size(elf, name):
    """Bytes of the object name in elf."""
    for line in run(["arm-none-eabi-nm", "-S", elf]).splitlines():
        parts = line.split()
        if len(parts) == 4 and parts[3] == name:
            return int(parts[1], 16)
    raise SystemExit(f"{elf}: no object named {name}")


def sizes(elf):
    """(flash, ram): text + data + the unwind index; data + bss."""
    sections = {}
    for line in run(["arm-none-eabi-size", "-A", elf]).splitlines():
        m = re.match(r"^(\.\S+)\s+(\d+)\s", line)
        if m:
            sections[m.group(1)] = int(m.group(2))
    flash = sections.get(".text", 0) + sections.get(".data", 0) + sections.get(".ARM.exidx", 0)
    ram = sections.get(".data", 0) + sections.get(".bss", 0)
    return flash, ram


def code_by_file(elf_map):
    """Bytes of code and constants by source file, from the link map."""
    total = defaultdict(int)
    with open(elf_map) as f:
        text = f.read()
    text = text[text.index("Linker script and memory map"):]  # not the discarded sections
    # \s+ also takes the line break after a name too long for its column.
    for m in re.finditer(r"^ \.(?:text|rodata)\S*\s+0x[0-9a-f]+\s+0x([0-9a-f]+)\s+\S*\(([^)]+)\.obj\)",
                         text, re.M):
        total[m.group(2)] += int(m.group(1), 16)
    return total


def kilobot_medians():
    """The Kilobot's medians (cycles) as bench/avr_bench.py last wrote them,
    by the start of their row's name (the first row that starts so; its
    median is the column so headed)."""
    medians = {}
    with open(os.path.join(ROOT, "docs", "benchmarks.md")) as f:
        text = f.read()
    text = text[:text.index(BEGIN)] if BEGIN in text else text
    header = re.search(r"^\| what \|.*\| median \|.*$", text, re.M)
    if not header:
        return medians
    column = [c.strip() for c in header.group(0).split("|")].index("median")
    for key in ("port_switch", "Sys_Yield", "tick interrupt", "interrupt to event handler",
                "interrupt to woken thread", "event send from a thread to its handler and back"):
        m = re.search(r"^\| " + re.escape(key) + r".*$", text, re.M)
        if m:
            medians[key] = m.group(0).split("|")[column].strip()
    return medians


def main():
    build()
    found = samples()
    kilobot = kilobot_medians()
    rows = [
        ("port_switch, thread to thread (assembly, no kernel)", "port_switch", kilobot.get("port_switch", "")),
        ("Sys_Yield, thread to thread (kernel decision + switch)", "yield", kilobot.get("Sys_Yield", "")),
        ("tick interrupt to the next thread (preemptive switch)", "tick_switch", kilobot.get("tick interrupt", "")),
        ("interrupt to event handler (an ISR sends, the handler runs)", "irq_to_handler", kilobot.get("interrupt to event handler", "")),
        ("interrupt to woken thread (an ISR sends, a waiter of higher priority runs)", "irq_to_thread", kilobot.get("interrupt to woken thread", "")),
    ]
    fp = {v: sizes(os.path.join(BUILD, f"footprint_{v}.elf")) for v in ("base", "plus_thread", "plus_event", "minimal")}
    # A thread slot is a control block in os: the difference of its size.
    # (The images' RAM differs by 4 bytes more or less: where the linker
    # aligns the stack pool, which grows by the slot's frame.)
    tcb = symbol_size(os.path.join(BUILD, "footprint_plus_thread.elf"), "os") - \
        symbol_size(os.path.join(BUILD, "footprint_base.elf"), "os")
    per_event = fp["plus_event"][1] - fp["base"][1]
    by_file = code_by_file(os.path.join(BUILD_NOLTO, "footprint_base.map"))
    port_files = [f for f in by_file if f in ("port.c", "switch.S", "faults.c", "fault_report.c",
                                              "reset.c", "console_print.c", "stm32f407_vectors.c")]
    board_files = [f for f in by_file if f in ("board_qemu.c", "semihosting.c", "board_record.c",
                                               "devices_qemu.c")]
    kernel_files = [f for f in by_file if f.endswith(".c") and f not in port_files + board_files
                    and f != "footprint_app.c" and "lib_a" not in f]
    kernel_bytes = sum(by_file[f] for f in kernel_files)
    port_bytes = sum(by_file[f] for f in port_files)
    board_bytes = sum(by_file[f] for f in board_files)
    with open(os.path.join(ROOT, "bench", "avr", "footprint_base.h")) as f:
        pool = int([l for l in f if "STACK_POOL_BYTES" in l][0].split()[2])
    ram = fp["base"][1] - pool - STACK_EXTRA
    fixed = ram - tcb * 2 - per_event * 6

    out = [BEGIN, "## The e-puck2's Cortex-M4 under QEMU\n",
           f"Measured by `{COMMAND}`: firmware `bench/qemu/`, built with arm-none-eabi-gcc -Os\n"
           "-flto, run in QEMU 7.2's netduinoplus2 with `-icount shift=0`, where every\n"
           "instruction is one nanosecond of virtual time and TIM2 counts them. These are\n"
           "**instructions, not cycles**: a real STM32F407 at 168 MHz adds flash wait states,\n"
           "pipeline refills and 12 cycles or more per exception entry. Each figure runs from\n"
           "the counter read before the operation to the first read after it in the other\n"
           "context (the reads included); interrupt figures start when the interrupt is raised\n"
           "(a write to NVIC STIR; for the tick, SysTick's own count).\n",
           "| what | min | median | max | samples | Kilobot (cycles, median) |",
           "|---|---:|---:|---:|---:|---:|"]
    for name, key, avr in rows:
        s = found.get(key, [])
        if s:
            out.append(f"| {name} | {min(s)} | {int(statistics.median(s))} | {max(s)} | {len(s)} | {avr} |")
        else:
            out.append(f"| {name} | | (no samples) | | 0 | {avr} |")
    send = found.get("send_to_handler_x100", [0])[0] / 100
    out.append(f"| event send from a thread to its handler and back, per event | | {send:.0f} | | 100 | {kilobot.get('event send from a thread to its handler and back', '')} |\n")
    out.append("The epilogue of an interrupt that may switch threads (PendSV into thread mode, the\n"
               "kernel's decision, SVC back: `ports/cortex_m4/README.md`) runs after every\n"
               "kernel-aware interrupt, whether it switches or not: it is most of the difference\n"
               "between an interrupt's cost here and on the ATmega328P, whose handler decides in place.\n")
    out.append("### Footprint and the paper's equation (1)\n")
    out.append("The Kilobot benchmark's minimal app and configurations (`bench/avr/footprint_*.h`:\n"
               "2 thread slots, 6 event slots, 1 subscription, a 16-byte queue), built for the\n"
               "QEMU board.\n")
    out.append("| what | bytes |")
    out.append("|---|---:|")
    out.append(f"| whole image: flash (text + data) | {fp['base'][0]} |")
    out.append(f"| whole image: RAM (data + bss; the two stacks of 2 + 8 KB excluded) | {fp['base'][1]} |")
    out.append(f"| without LTO, from the link map: kernel code (`kernel/src`) | {kernel_bytes} |")
    out.append(f"| without LTO: Cortex-M4 port (switch, epilogue, tick, faults, reset, vector table) | {port_bytes} |")
    out.append(f"| without LTO: QEMU board (console, semihosting, records, status light) | {board_bytes} |")
    out.append(f"| the same image without the optional features (`footprint_minimal.h`) | {fp['minimal'][0]} |")
    out.append(f"| kernel + port RAM with one thread slot (stack pool and frame excluded) | {ram} |")
    out.append(f"| per extra thread slot: its control block (the pool also grows by its {STACK_EXTRA}-byte frame) | {tcb} |")
    out.append(f"| per extra event slot (data excluded) | {per_event} |\n")
    out.append("So the kernel's RAM on the Cortex-M4 for n user threads and m application events is about\n\n"
               f"    {fixed + tcb + per_event * 6} + {tcb} n + {per_event} m + sum(d_i) + sum(stack_i + {STACK_EXTRA})\n\n"
               "against the paper's 1142 + 146 n + 6 m + sum(d_i) on the dsPIC (its 146 B per thread\n"
               "include a 128-byte stack). The 384-byte frame per thread is the price of 32-bit\n"
               "registers and the FPU: a switch frame with s16-s31 and an interrupt's extended frame.\n")
    out.append(END)
    section = "\n".join(out)
    benchmarks_page.write_section(BEGIN, END, section)
    print(section)


if __name__ == "__main__":
    main()
