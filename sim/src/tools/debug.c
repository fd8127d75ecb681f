/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* Debugging a robot: avr-gdb's remote protocol, and GTKWave traces. */
#define _GNU_SOURCE /* fopencookie */
#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include <avr_ioport.h>
#include <avr_timer.h>
#include <sim_gdb.h>
#include <sim_io.h>

#include "sim.h"

/* The file is tried first here: simavr's own attempt prints its own
 * message and leaves errno to whatever its cleanup did. */
static int vcd_writable(const char *path) {
    FILE *f = fopen(path, "w");
    if (f == NULL) {
        fprintf(stderr, "openswarm-sim: --vcd %s: cannot create the file (%s); give a path in a writable folder\n",
                path, strerror(errno));
        return 0;
    }
    fclose(f);
    return 1;
}

/* simavr writes the trace through its own FILE and closes it without
 * telling how that went: its FILE is swapped for one that writes to the
 * same file and keeps the first error (one robot has a --vcd). */
static struct {
    int fd;
    int error; /* errno of the first failed write or close; 0: none */
} vcd_sink = {-1, 0};

static ssize_t vcd_sink_write(void *cookie, const char *bytes, size_t n) {
    (void)cookie;
    size_t done = 0;
    while (done < n) {
        ssize_t w = write(vcd_sink.fd, bytes + done, n - done);
        if (w < 0 && errno == EINTR) continue;
        if (w <= 0) {
            if (vcd_sink.error == 0) vcd_sink.error = w < 0 ? errno : EIO;
            return -1;
        }
        done += (size_t)w;
    }
    return (ssize_t)n;
}

static int vcd_sink_close(void *cookie) {
    (void)cookie;
    if (close(vcd_sink.fd) != 0 && vcd_sink.error == 0) vcd_sink.error = errno;
    vcd_sink.fd = -1;
    return 0;
}

static int vcd_watch(robot *r) {
    FILE *theirs = r->vcd.output;
    if (theirs == NULL) return 0;
    int header = fflush(theirs) != 0 ? errno : 0; /* what avr_vcd_start wrote */
    vcd_sink.fd = dup(fileno(theirs));
    vcd_sink.error = header;
    cookie_io_functions_t io = {NULL, vcd_sink_write, NULL, vcd_sink_close};
    FILE *ours = vcd_sink.fd >= 0 ? fopencookie(NULL, "w", io) : NULL;
    if (ours == NULL) {
        if (vcd_sink.fd >= 0) close(vcd_sink.fd);
        vcd_sink.fd = -1;
        return 0; /* as it was: simavr's own FILE */
    }
    fclose(theirs);
    r->vcd.output = ours;
    return 0;
}

static int vcd_open(robot *r, const char *path) {
    avr_t *avr = r->avr;
    if (!vcd_writable(path)) return -1;
    if (avr_vcd_init(avr, path, &r->vcd, 1000) != 0) {
        fprintf(stderr, "openswarm-sim: --vcd %s: cannot create the file\n", path);
        return -1;
    }
    avr_vcd_add_signal(&r->vcd, avr_io_getirq(avr, AVR_IOCTL_IOPORT_GETIRQ('C'), IOPORT_IRQ_DIRECTION_ALL), 8, "ddrc_led_green_blue");
    avr_vcd_add_signal(&r->vcd, avr_io_getirq(avr, AVR_IOCTL_IOPORT_GETIRQ('D'), IOPORT_IRQ_DIRECTION_ALL), 8, "ddrd_led_red");
    avr_vcd_add_signal(&r->vcd, avr_io_getirq(avr, AVR_IOCTL_TIMER_GETIRQ('2'), TIMER_IRQ_OUT_PWM0), 8, "motor_left");
    avr_vcd_add_signal(&r->vcd, avr_io_getirq(avr, AVR_IOCTL_TIMER_GETIRQ('2'), TIMER_IRQ_OUT_PWM1), 8, "motor_right");
    /* The file is created here: a folder that is missing or not writable
     * fails the run (it ran without a trace, exit 0). */
    if (avr_vcd_start(&r->vcd) != 0) {
        fprintf(stderr, "openswarm-sim: --vcd %s: cannot create the file; give a path in a writable folder\n", path);
        avr_vcd_close(&r->vcd);
        return -1;
    }
    r->vcd_open = 1;
    return vcd_watch(r);
}

int debug_attach(robot *r, const options *o) {
    if (o->vcd != NULL && vcd_open(r, o->vcd) != 0) return -1;
    if (o->gdb_port != 0) {
        r->avr->gdb_port = o->gdb_port;
        r->avr->state = cpu_Stopped;
        avr_gdb_init(r->avr);
        fprintf(stderr, "openswarm-sim: waiting for avr-gdb: avr-gdb -ex 'target remote :%d' %s\n",
                o->gdb_port, o->elves[0]);
    }
    return 0;
}

int debug_detach(robot *r) {
    if (!r->vcd_open) return 0;
    char path[4096];
    snprintf(path, sizeof path, "%s", r->vcd.filename ? r->vcd.filename : "");
    avr_vcd_close(&r->vcd);
    r->vcd_open = 0;
    if (vcd_sink.error == 0) return 0;
    fprintf(stderr, "openswarm-sim: --vcd %s: cannot write it: %s; what the run wrote there is "
                    "incomplete: free some room on its disk, or write it elsewhere\n",
            path, strerror(vcd_sink.error));
    return -1;
}
