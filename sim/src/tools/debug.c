/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* Debugging a robot: avr-gdb's remote protocol, and GTKWave traces. */
#include <errno.h>
#include <string.h>

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
    return 0;
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

void debug_detach(robot *r) {
    if (r->vcd_open) avr_vcd_close(&r->vcd);
}
