/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* A firmware ELF's symbol table, walked once for whoever needs names and
 * addresses (the profiler's functions, the main stack's floor). */
#include <fcntl.h>
#include <string.h>
#include <gelf.h>
#include <unistd.h>

#include "sim.h"

static void each_in(Elf *elf, Elf_Scn *scn, const GElf_Shdr *shdr, firmware_symbol_fn each, void *ctx) {
    Elf_Data *data = elf_getdata(scn, NULL);
    size_t n = shdr->sh_entsize ? shdr->sh_size / shdr->sh_entsize : 0;
    for (size_t i = 0; i < n; i++) {
        GElf_Sym sym;
        if (gelf_getsym(data, (int)i, &sym) == NULL) continue;
        const char *name = elf_strptr(elf, shdr->sh_link, sym.st_name);
        each(name, (uint32_t)sym.st_value, (uint32_t)sym.st_size,
             GELF_ST_TYPE(sym.st_info), ctx);
    }
}

int firmware_symbols(const char *path, firmware_symbol_fn each, void *ctx) {
    elf_version(EV_CURRENT);
    int fd = open(path, O_RDONLY);
    Elf *elf = fd < 0 ? NULL : elf_begin(fd, ELF_C_READ, NULL);
    if (elf == NULL) {
        if (fd >= 0) close(fd);
        return -1;
    }
    for (Elf_Scn *scn = NULL; (scn = elf_nextscn(elf, scn)) != NULL;) {
        GElf_Shdr shdr;
        if (gelf_getshdr(scn, &shdr) != NULL && shdr.sh_type == SHT_SYMTAB) each_in(elf, scn, &shdr, each, ctx);
    }
    elf_end(elf);
    close(fd);
    return 0;
}

int symbol_named(const char *name, const char *wanted) {
    size_t n = strlen(wanted);
    return strncmp(name, wanted, n) == 0 && (name[n] == '\0' || name[n] == '.');
}

void firmware_symbols_once(const char *path, const char **read_path, firmware_symbol_fn each,
                           void *answer, size_t size) {
    if (path == *read_path) return;
    memset(answer, 0, size);
    firmware_symbols(path, each, answer);
    *read_path = path;
}
