/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
#include "world/epuck_link.h"

#include "link_io.h" /* the robot's end has the same (ports/epuck/host) */

#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

/* Why the controller is gone, reaped. */
static void report_gone(epuck_link *l, const char *doing) {
    int status = 0;
    pid_t done = l->pid > 0 ? waitpid(l->pid, &status, 0) : -1;
    l->pid = 0;
    if (done > 0 && WIFEXITED(status))
        fprintf(stderr, "openswarm-sim: robot %d's controller %s exited with status %d while %s\n",
                l->index, l->controller, WEXITSTATUS(status), doing);
    else if (done > 0 && WIFSIGNALED(status))
        fprintf(stderr, "openswarm-sim: robot %d's controller %s was killed by signal %d (%s) while %s\n",
                l->index, l->controller, WTERMSIG(status), strsignal(WTERMSIG(status)), doing);
    else
        fprintf(stderr, "openswarm-sim: robot %d's controller %s stopped answering while %s\n",
                l->index, l->controller, doing);
}

int epuck_link_start(epuck_link *l, const char *controller, int index, epuck_world_output *first) {
    int down[2], up[2];
    l->index = index;
    l->controller = controller;
    signal(SIGPIPE, SIG_IGN); /* a controller that died is reported, not fatal */
    if (pipe(down) != 0 || pipe(up) != 0) {
        fprintf(stderr, "openswarm-sim: cannot start robot %d's controller: %s\n", index, strerror(errno));
        return -1;
    }
    l->pid = fork();
    if (l->pid == 0) {
        dup2(down[0], STDIN_FILENO);
        dup2(up[1], STDOUT_FILENO);
        close(down[0]), close(down[1]), close(up[0]), close(up[1]);
        char id[16]; /* the robot's robot_id() (ports/epuck/host/src/robot_world.c) */
        snprintf(id, sizeof id, "%d", index);
        setenv("OPENSWARM_ROBOT_ID", id, 1);
        execl(controller, controller, (char *)NULL);
        fprintf(stderr, "openswarm-sim: cannot run %s: %s\n", controller, strerror(errno));
        _exit(127);
    }
    close(down[0]);
    close(up[1]);
    l->to = down[1];
    l->from = up[0];
    if (l->pid < 0) {
        fprintf(stderr, "openswarm-sim: cannot start robot %d's controller: %s\n", index, strerror(errno));
        return -1;
    }
    return epuck_link_receive(l, first);
}

int epuck_link_send(epuck_link *l, const epuck_world_input *in, const uint16_t *pixels) {
    size_t n_pixels = (size_t)in->frame_width * in->frame_height;
    if (!link_write(l->to, in, sizeof *in) ||
        (n_pixels && !link_write(l->to, pixels, n_pixels * sizeof *pixels))) {
        report_gone(l, "taking its inputs");
        return -1;
    }
    return 0;
}

int epuck_link_receive(epuck_link *l, epuck_world_output *out) {
    if (link_read(l->from, out, sizeof *out) != sizeof *out) {
        report_gone(l, "running");
        return -1;
    }
    if (out->magic != EPUCK_LINK_MAGIC) {
        fprintf(stderr, "openswarm-sim: robot %d's controller %s answered 0x%08x, not an e-puck link "
                        "record: build it for the world (PORT epuck_world), and let it print only "
                        "to stderr\n",
                l->index, l->controller, (unsigned)out->magic);
        return -1;
    }
    return 0;
}

int epuck_link_stop(epuck_link *l) {
    if (l->pid <= 0) return -1;
    epuck_world_input stop = {EPUCK_LINK_MAGIC, 0, EPUCK_LINK_STOP, 0, {0}, {0}, 0, 0};
    epuck_world_output last;
    if (epuck_link_send(l, &stop, NULL) == 0) epuck_link_receive(l, &last);
    close(l->to);
    close(l->from);
    int status = 0;
    if (l->pid <= 0 || waitpid(l->pid, &status, 0) < 0) return -1;
    l->pid = 0;
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}
