/* The world link for a controller without the OS (openswarm/epuck_plain.h)
 * on the e-puck2 image under QEMU, as ports/epuck/host/src/plain_world.c is
 * for the host: the program's own loop drives the exchange, each input
 * answered once the program has had its say - at once for a step without
 * a frame; for a step with one, when the program asks for the next frame.
 * No kernel is started and no tick runs: the program's instructions are
 * all its CPU does: the account (cpu_account.h) counts the link's own work
 * apart, so its "other busy" is the program's, and prints it at the end,
 * as the kernel's board prints its own. */
#include <stdbool.h>

#include "../qemu/semihosting.h"
#include "cpu_account.h"
#include "openswarm/epuck_plain.h"
#include "world_link_io.h"

static uint16_t pixels[WORLD_LINK_MAX_PIXELS];
static epuck_camera_frame frame = {pixels, 0, 0, 0};
static uint32_t now_ms;
static int16_t wheel[2];
static bool owed; /* an input is still to be answered */

static void answer(void) {
    epuck_world_output out = {EPUCK_LINK_MAGIC, now_ms, wheel[0], wheel[1], 0, 0, 0, 0, 0};
    world_link_send(&out, sizeof out);
    owed = false;
}

void epuck_plain_start(void) {
    world_link_open();
    cpu_account_start();
    answer(); /* time 0: up */
}

const epuck_camera_frame *epuck_plain_wait_frame(void) {
    uint32_t link_since = cpu_account_now();
    for (;;) {
        if (owed) answer();
        epuck_world_input in;
        world_link_read_input(&in, pixels);
        now_ms += in.advance_ms;
        owed = true;
        if (in.flags & EPUCK_LINK_STOP) {
            cpu_account_add(CPU_LINK, link_since);
            cpu_account_report(false);
            answer();
            semihosting_exit(0);
        }
        if (in.frame_width != 0 && in.frame_height != 0) {
            frame.width = in.frame_width;
            frame.height = in.frame_height;
            cpu_account_add(CPU_LINK, link_since);
            return &frame;
        }
    }
}

void epuck_plain_set_wheels(int16_t left, int16_t right) {
    wheel[0] = epuck_plain_limit(left);
    wheel[1] = epuck_plain_limit(right);
}
