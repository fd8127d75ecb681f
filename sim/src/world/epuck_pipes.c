/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* e-puck controllers as host processes, one each, over a pipe
 * (epuck_link.h): all inputs go out first, so the processes run the step
 * side by side, then every answer is read. */
#include "world/epuck_controllers.h"

#include <stdlib.h>

#include "world/epuck_link.h"

static epuck_link *links;
static int n_links;

/* Each controller a program, or each an e-puck2 image in QEMU. */
static int start_them(const options *o, int n, int under_qemu, epuck_world_output *first) {
    links = calloc(n ? (size_t)n : 1, sizeof *links);
    if (links == NULL) {
        fprintf(stderr, "openswarm-sim: out of memory for %d e-pucks\n", n);
        return -1;
    }
    n_links = n;
    for (int i = 0; i < n; i++)
        if (epuck_link_start(&links[i], o->robot_elf[i], under_qemu, i, &first[i]) != 0) return -1;
    return 0;
}

static int start(const options *o, int n, epuck_world_output *first) { return start_them(o, n, 0, first); }

static int start_in_qemu(const options *o, int n, epuck_world_output *first) { return start_them(o, n, 1, first); }

static int send(int i, uint32_t t_ms, const epuck_world_input *in, const uint16_t *pixels) {
    links[i].t_ms = (int32_t)t_ms;
    return epuck_link_send(&links[i], in, pixels);
}

static int receive(int n, epuck_world_output *out) {
    for (int i = 0; i < n; i++)
        if (epuck_link_receive(&links[i], &out[i]) != 0) return -1;
    return 0;
}

/* Their kernels' losses come with their ends: noted as warnings here. */
static int stop(void) {
    int failed = 0;
    for (int i = 0; i < n_links; i++) {
        if (links[i].pid > 0 && epuck_link_stop(&links[i]) != 0) failed = -1;
        if (links[i].has_losses) kernel_loss_warnings(i, ROBOT_EPUCK, links[i].losses.counters);
    }
    return failed;
}

const epuck_controllers epuck_pipes = {start, send, receive, stop, NULL};
const epuck_controllers epuck_qemu = {start_in_qemu, send, receive, stop, NULL};
