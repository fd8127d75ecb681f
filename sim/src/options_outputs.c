/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* No output of a run overwrites one of its inputs. */
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "sim.h"

/* An input the run reads, which no output may be. */
typedef struct input_file {
    const char *path;
    char what[64]; /* "the world file", "robot 3's firmware" */
    struct stat st;
} input_file;

/* The first input that is the same file as path (an existing one), or NULL. */
static const input_file *input_at(const input_file *inputs, int n, const char *path) {
    struct stat st;
    if (stat(path, &st) != 0) return NULL; /* not there yet: no input */
    for (int k = 0; k < n; k++)
        if (inputs[k].st.st_dev == st.st_dev && inputs[k].st.st_ino == st.st_ino) return &inputs[k];
    return NULL;
}

/* No output may overwrite an input (a world file named trajectories.csv
 * with --out ., --trace-csv naming the firmware): compared by device and
 * inode, so any spelling of the path and links are caught. */
int outputs_apart_from_inputs(const options *o) {
    int room = 2 + (o->robots > 0 ? o->robots : 0), n = 0, status = 0;
    input_file *inputs = calloc((size_t)room, sizeof *inputs);
    if (inputs == NULL) return 0;
#define INPUT(p, ...)                                                                         \
    do {                                                                                      \
        if ((p) != NULL && stat((p), &inputs[n].st) == 0) {                                   \
            inputs[n].path = (p);                                                             \
            snprintf(inputs[n].what, sizeof inputs[n].what, __VA_ARGS__);                     \
            n++;                                                                              \
        }                                                                                     \
    } while (0)
    INPUT(o->world, "the world file");
    INPUT(o->positions, "the --positions file");
    const char *previous = NULL;
    for (int i = 0; i < o->robots; i++) {
        const char *elf = firmware_of(o, i);
        if (elf == NULL || (previous != NULL && strcmp(elf, previous) == 0)) continue;
        INPUT(elf, "robot %d's firmware", i);
        previous = elf;
    }
#undef INPUT
    const struct {
        const char *option, *path;
    } files[] = {{"--trace-csv", o->trace_csv}, {"--vcd", o->vcd}, {"--fault-log", o->fault_log},
                 {"--console-csv", o->console_csv}};
    for (size_t k = 0; status == 0 && k < sizeof files / sizeof files[0]; k++) {
        const input_file *in = files[k].path ? input_at(inputs, n, files[k].path) : NULL;
        if (in == NULL) continue;
        fprintf(stderr, "openswarm-sim: %s %s is %s %s: the run would overwrite it; give %s another file\n",
                files[k].option, files[k].path, in->what, in->path, files[k].option);
        status = -1;
    }
    static const char *written[] = {"trajectories.csv", "objects.csv", "final.png", "viewer.html",
                                    "video.mp4"};
    for (size_t k = 0; status == 0 && o->out_dir != NULL && k < sizeof written / sizeof written[0]; k++) {
        if (k == 4 && !o->video) continue;
        char path[4096];
        size_t len = strlen(o->out_dir);
        snprintf(path, sizeof path, "%s%s%s", o->out_dir, len && o->out_dir[len - 1] == '/' ? "" : "/",
                 written[k]);
        const input_file *in = input_at(inputs, n, path);
        if (in == NULL) continue;
        fprintf(stderr, "openswarm-sim: --out %s: its %s is %s %s: the run would overwrite it; give "
                        "another --out folder, or rename %s\n",
                o->out_dir, written[k], in->what, in->path, in->what);
        status = -1;
    }
    free(inputs);
    return status;
}
