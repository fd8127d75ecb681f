#include "world_link_io.h"

#include "../qemu/semihosting.h"
#include "openswarm/cortex_m4.h"

static int32_t world_in = -1, world_out = -1; /* QEMU's standard input and output */

void world_link_broken(const char *why) {
    cortex_m4_print("epuck world link: ");
    cortex_m4_print(why);
    cortex_m4_print("\n");
    semihosting_exit(2);
}

void world_link_open(void) {
    world_in = semihosting_open("/dev/stdin", false);
    world_out = semihosting_open("/dev/stdout", true);
    if (world_in < 0 || world_out < 0)
        world_link_broken("cannot open QEMU's standard input and output: run QEMU with "
                          "-semihosting-config enable=on,target=native");
}

void world_link_send(const void *data, size_t length) {
    if (!semihosting_write(world_out, data, (uint32_t)length)) world_link_broken("the world stopped reading");
}

/* A pipe's read may return part of a record: the rest follows. */
static void receive(void *data, size_t length) {
    uint8_t *p = data;
    for (size_t done = 0; done < length;) {
        uint32_t n = semihosting_read(world_in, p + done, (uint32_t)(length - done));
        if (n == 0) world_link_broken("the world closed the link mid-run");
        done += n;
    }
}

void world_link_read_input(epuck_world_input *in, uint16_t *pixels) {
    receive(in, sizeof *in);
    if (in->magic != EPUCK_LINK_MAGIC) world_link_broken("an input that is not an e-puck link record");
    uint32_t n = (uint32_t)in->frame_width * in->frame_height;
    if (n > WORLD_LINK_MAX_PIXELS) world_link_broken("a frame larger than 80 x 60");
    receive(pixels, n * sizeof pixels[0]);
}
