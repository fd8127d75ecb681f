/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* Copies of a native robot (native_load.h). The dynamic linker loads a
 * file once however often it is opened, so each copy is the file's bytes
 * in a memory file of its own (memfd), opened by its /proc path. A copy's
 * RAM image is its writable segment past the part made read-only after
 * relocation (RELRO: the GOT, constant pointers): what the robot's code
 * writes, .data and .bss. */
#define _GNU_SOURCE
#include "native/native_load.h"

#include <dlfcn.h>
#include <elf.h>
#include <errno.h>
#include <link.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <unistd.h>

/* A host shared object: position-independent, and no program (a program
 * names its dynamic linker, PT_INTERP). */
int native_is_robot(const char *path) {
    FILE *f = fopen(path, "rb");
    if (f == NULL) return 0;
    Elf64_Ehdr h;
    int yes = fread(&h, sizeof h, 1, f) == 1 && memcmp(h.e_ident, ELFMAG, SELFMAG) == 0 &&
              h.e_ident[EI_CLASS] == ELFCLASS64 && h.e_type == ET_DYN && h.e_machine == EM_X86_64;
    for (int i = 0; yes && i < h.e_phnum; i++) {
        Elf64_Phdr p;
        if (fseek(f, (long)(h.e_phoff + (uint64_t)i * h.e_phentsize), SEEK_SET) != 0 ||
            fread(&p, sizeof p, 1, f) != 1 || p.p_type == PT_INTERP)
            yes = 0;
    }
    fclose(f);
    return yes;
}

static uint8_t *read_file(const char *path, size_t *size) {
    FILE *f = fopen(path, "rb");
    if (f == NULL) return NULL;
    uint8_t *bytes = NULL;
    if (fseek(f, 0, SEEK_END) == 0) {
        long n = ftell(f);
        if (n > 0 && fseek(f, 0, SEEK_SET) == 0 && (bytes = malloc((size_t)n)) != NULL &&
            fread(bytes, 1, (size_t)n, f) != (size_t)n) {
            free(bytes);
            bytes = NULL;
        }
        *size = n > 0 ? (size_t)n : 0;
    }
    fclose(f);
    return bytes;
}

/* The copy's memory file stays open (*fd) for the whole run: the dynamic
 * linker also knows an object by its path, and a later copy - of this app
 * or of another app of the world - given the same descriptor number would
 * be taken for this one. */
static void *open_copy(const uint8_t *bytes, size_t size, int k, int *fd, char *why, size_t why_room) {
    *fd = memfd_create("openswarm-native-robot", MFD_CLOEXEC);
    if (*fd < 0 || write(*fd, bytes, size) != (ssize_t)size) {
        snprintf(why, why_room, "cannot copy it into memory (%s)", strerror(errno));
        return NULL;
    }
    char proc[64];
    snprintf(proc, sizeof proc, "/proc/self/fd/%d", *fd);
    void *handle = dlopen(proc, RTLD_NOW | RTLD_LOCAL);
    if (handle == NULL) snprintf(why, why_room, "copy %d: %s", k, dlerror());
    return handle;
}

/* The writable segment of the object at base, past its RELRO part. */
typedef struct image_search {
    uintptr_t base;
    uintptr_t start, end;
} image_search;

static int find_image(struct dl_phdr_info *info, size_t size, void *ctx) {
    (void)size;
    image_search *s = ctx;
    if (info->dlpi_addr != s->base) return 0;
    uintptr_t relro_end = 0;
    for (int i = 0; i < info->dlpi_phnum; i++) {
        const ElfW(Phdr) *p = &info->dlpi_phdr[i];
        uintptr_t lo = s->base + p->p_vaddr, hi = lo + p->p_memsz;
        if (p->p_type == PT_LOAD && (p->p_flags & PF_W)) {
            s->start = lo;
            s->end = hi;
        } else if (p->p_type == PT_GNU_RELRO) {
            relro_end = hi;
        }
    }
    if (relro_end > s->start && relro_end <= s->end) s->start = relro_end;
    return 1;
}

static int describe(const char *path, native_copy *c) {
    native_describe_fn fn = (native_describe_fn)dlsym(c->handle, NATIVE_DESCRIBE_SYMBOL);
    if (fn == NULL) {
        fprintf(stderr, "openswarm-sim: %s is a shared object but no native robot (no %s): build "
                        "the app with `openswarm build --native`\n", path, NATIVE_DESCRIBE_SYMBOL);
        return -1;
    }
    fn(&c->entry);
    if (c->entry.abi != NATIVE_ROBOT_ABI) {
        fprintf(stderr, "openswarm-sim: %s was built for another simulator (native ABI %u, this one "
                        "runs %u): build it again with this OpenSwarm (`openswarm build --native`)\n",
                path, c->entry.abi, NATIVE_ROBOT_ABI);
        return -1;
    }
    struct link_map *map;
    if (dlinfo(c->handle, RTLD_DI_LINKMAP, &map) != 0) return -1;
    c->base = map->l_addr;
    image_search s = {map->l_addr, 0, 0};
    dl_iterate_phdr(find_image, &s);
    if (s.end <= s.start) {
        fprintf(stderr, "openswarm-sim: %s: no writable segment found: is it a native robot?\n", path);
        return -1;
    }
    c->image = (uint8_t *)s.start;
    c->image_bytes = s.end - s.start;
    c->pristine = malloc(c->image_bytes);
    if (c->pristine == NULL) return -1;
    memcpy(c->pristine, c->image, c->image_bytes);
    return 0;
}

int native_load(const char *path, int copies, native_copy *out) {
    size_t size = 0;
    uint8_t *bytes = read_file(path, &size);
    if (bytes == NULL) {
        fprintf(stderr, "openswarm-sim: %s: cannot read it (%s)\n", path, strerror(errno));
        return -1;
    }
    int status = 0;
    for (int k = 0; k < copies && status == 0; k++) {
        char why[512];
        int fd; /* left open: open_copy */
        out[k].handle = open_copy(bytes, size, k, &fd, why, sizeof why);
        if (out[k].handle == NULL) {
            fprintf(stderr, "openswarm-sim: %s: cannot load it as a native robot: %s\n", path, why);
            status = -1;
        } else {
            status = describe(path, &out[k]);
        }
    }
    free(bytes);
    return status;
}
