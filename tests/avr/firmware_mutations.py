#!/usr/bin/env python3
"""openswarm-sim on damaged firmware: a real ELF and its .hex, each mutated a
few hundred ways (fixed seed: the same files on every run), each run for a
moment. None may crash the simulator (a signal, a status of 128 or more, a
sanitizer's report) or hang; each either runs or is refused with exit status
2 and one line naming the file.

    firmware_mutations.py SIMULATOR FIRMWARE.elf WORKDIR [ELF_MUTANTS HEX_MUTANTS]
"""
import os
import random
import shutil
import subprocess
import sys

SEED = 14  # the hardening issue's number: any fixed value will do
ELF_HEADER, PHDR, SHDR = 52, 32, 40


def u16(b, at):
    return b[at] | b[at + 1] << 8


def u32(b, at):
    return b[at] | b[at + 1] << 8 | b[at + 2] << 16 | b[at + 3] << 24


def structure(elf):
    """Byte ranges libsimavr's reader trusts: the headers, both header
    tables, the string and symbol tables and the .mmcu record."""
    ranges = [(0, ELF_HEADER)]
    phoff, shoff, phnum, shnum = u32(elf, 28), u32(elf, 32), u16(elf, 44), u16(elf, 48)
    ranges.append((phoff, phoff + phnum * PHDR))
    ranges.append((shoff, shoff + shnum * SHDR))
    for i in range(shnum):
        at = shoff + i * SHDR
        kind, offset, size = u32(elf, at + 4), u32(elf, at + 16), u32(elf, at + 20)
        if kind in (2, 3) or (kind == 1 and u32(elf, at + 12) >= 0x900000):  # SYMTAB, STRTAB, .mmcu
            ranges.append((offset, offset + size))
    return [(a, b) for a, b in ranges if b > a]


def mutate_elf(elf, rng):
    data = bytearray(elf)
    if rng.random() < 0.1:
        return bytes(data[: rng.randrange(len(data))])  # cut short
    ranges = structure(elf)
    for _ in range(rng.randint(1, 4)):
        if rng.random() < 0.7:
            start, end = rng.choice(ranges)
            at = rng.randrange(start, end)
        else:
            at = rng.randrange(len(data))
        data[at] = rng.choice([0, 0xFF, 0x80, 0x7F, rng.randrange(256), data[at] ^ (1 << rng.randrange(8))])
    return bytes(data)


def mutate_hex(text, rng):
    data = bytearray(text)
    for _ in range(rng.randint(1, 3)):
        at = rng.randrange(len(data))
        choice = rng.random()
        if choice < 0.6:
            data[at] = ord(rng.choice("0123456789ABCDEF:\n"))
        elif choice < 0.8:
            del data[at]
        else:
            data = data[:at]
            break
    return bytes(data)


def run(simulator, path):
    """(status, stderr) of a short run; status None if it hung."""
    try:
        done = subprocess.run([simulator, "--time", "0.002", "--quiet", path], stdout=subprocess.DEVNULL,
                              stderr=subprocess.PIPE, timeout=30)
    except subprocess.TimeoutExpired:
        return None, ""
    return done.returncode, done.stderr.decode("utf-8", "replace")


def verdict(path, status, err):
    """None if the outcome is allowed, else what went wrong."""
    if status is None:
        return "hung (no end within 30 s)"
    if status < 0 or status >= 128:
        return "crashed (status %d)" % status
    if "Sanitizer" in err:
        return "sanitizer report"
    if status == 2:
        prefix = "openswarm-sim: %s: " % path
        if not any(line.startswith(prefix) and len(line) > len(prefix) for line in err.splitlines()):
            return "refused without saying why"
    return None


def main():
    simulator, elf_path, work = sys.argv[1:4]
    elf_mutants, hex_mutants = (int(n) for n in (sys.argv[4:6] or (300, 100)))
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    elf = open(elf_path, "rb").read()
    hex_path = os.path.join(work, "base.hex")
    subprocess.run(["avr-objcopy", "-O", "ihex", "-j", ".text", "-j", ".data", elf_path, hex_path], check=True)
    hex_text = open(hex_path, "rb").read()
    rng = random.Random(SEED)
    mutants = [("elf", mutate_elf(elf, rng)) for _ in range(elf_mutants)]
    mutants += [("hex", mutate_hex(hex_text, rng)) for _ in range(hex_mutants)]
    counts = {"ran": 0, "refused": 0}
    failures = []
    for i, (kind, content) in enumerate(mutants):
        path = os.path.join(work, "m%03d.%s" % (i, kind))
        with open(path, "wb") as f:
            f.write(content)
        status, err = run(simulator, path)
        problem = verdict(path, status, err)
        if problem:
            failures.append("%s: %s\n%s" % (path, problem, err[-400:]))
            continue
        counts["refused" if status == 2 else "ran"] += 1
        os.remove(path)  # failures stay, to be looked at
    print("%d mutants: %d ran, %d refused with a reason, %d failed"
          % (len(mutants), counts["ran"], counts["refused"], len(failures)))
    for failure in failures[:20]:
        print("FAILED: " + failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
