/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* The main stack's worst use. main(), the interrupts and, under the
 * OpenSwarm kernel, the event handlers run on the stack that grows down
 * from RAMEND towards the RAM the image reserves (its end: _end).
 * The linker checks only that reservation, so an app whose thread stacks
 * leave the main stack no room builds and then crashes. Before the
 * firmware starts, the simulator paints the room between with a pattern;
 * at the end, the lowest byte that changed tells how deep the stack went
 * (a frame reserved deeper but never written would not show). */
#include <fcntl.h>
#include <gelf.h>
#include <string.h>
#include <unistd.h>

#include "sim.h"

#define PAINT 0xA5
/* Data-space addresses in the ELF are offset by this (avr-libc's scripts). */
#define AVR_DATA_OFFSET 0x800000u

/* The value of symbol name in the ELF at path; 0 if it has none. */
static uint32_t elf_symbol(const char *path, const char *name) {
    elf_version(EV_CURRENT);
    int fd = open(path, O_RDONLY);
    Elf *elf = fd < 0 ? NULL : elf_begin(fd, ELF_C_READ, NULL);
    uint32_t value = 0;
    for (Elf_Scn *scn = NULL; elf != NULL && value == 0 && (scn = elf_nextscn(elf, scn)) != NULL;) {
        GElf_Shdr shdr;
        if (gelf_getshdr(scn, &shdr) == NULL || shdr.sh_type != SHT_SYMTAB) continue;
        Elf_Data *data = elf_getdata(scn, NULL);
        size_t n = shdr.sh_entsize ? shdr.sh_size / shdr.sh_entsize : 0;
        for (size_t i = 0; i < n; i++) {
            GElf_Sym sym;
            if (gelf_getsym(data, (int)i, &sym) == NULL) continue;
            const char *s = elf_strptr(elf, shdr.sh_link, sym.st_name);
            if (s != NULL && strcmp(s, name) == 0) {
                value = (uint32_t)sym.st_value;
                break;
            }
        }
    }
    if (elf != NULL) elf_end(elf);
    if (fd >= 0) close(fd);
    return value;
}

void main_stack_paint(robot *r, const char *elf_path) {
    /* Unmeasured: a .hex (no symbols), or a firmware whose heap grows
     * into the same room (malloc). */
    uint32_t end = elf_symbol(elf_path, "_end");
    r->main_stack_floor = 0;
    if (end < AVR_DATA_OFFSET || end - AVR_DATA_OFFSET > r->avr->ramend) return;
    if (elf_symbol(elf_path, "malloc") != 0) return;
    r->main_stack_floor = (uint16_t)(end - AVR_DATA_OFFSET);
    memset(r->avr->data + r->main_stack_floor, PAINT, r->avr->ramend + 1u - r->main_stack_floor);
}

/* Bytes of the main stack used at worst (0 if it was not measured), and
 * the room it had. */
static unsigned worst_use(const robot *r, unsigned *room) {
    *room = r->main_stack_floor ? r->avr->ramend + 1u - r->main_stack_floor : 0;
    if (!r->main_stack_floor) return 0;
    unsigned a = r->main_stack_floor;
    while (a <= r->avr->ramend && r->avr->data[a] == PAINT) a++;
    return r->avr->ramend + 1u - a;
}

int main_stack_report(const robot *r, int print) {
    unsigned room, used = worst_use(r, &room);
    if (room == 0) return 0;
    if (print)
        fprintf(stderr, "openswarm-sim: %smain stack: worst use %u of %u bytes\n", r->console.prefix,
                used, room);
    if (used < room) return 0;
    fprintf(stderr, "openswarm-sim: %sthe main stack (main, interrupts, event handlers) ran into "
                    "the RAM the image reserves (it had %u bytes) and overwrote what lies there; give it more by lowering the "
                    "threads' \"stack\" in openswarm.json\n",
            r->console.prefix, room);
    return 1;
}
