/* The world link's records (openswarm/epuck_world_link.h) between the
 * e-puck2 image under QEMU and the world simulator, over QEMU's standard
 * input and output through semihosting: shared by the kernel's board
 * (board_world_link.c) and the plain loop's (plain_world_qemu.c).
 *
 * Why semihosting and not a serial port: QEMU's USART takes one byte per
 * pass of its main loop and wakes the CPU for each, about two host context
 * switches a byte; a step's inputs are 48 bytes and a camera frame 2400.
 * A semihosting read is one blocking read() of QEMU's for the whole
 * record, so a step costs QEMU one wake-up (docs/benchmarks.md, "The
 * e-puck2 image in the world"). */
#ifndef EPUCK2_QEMU_WORLD_LINK_IO_H
#define EPUCK2_QEMU_WORLD_LINK_IO_H

#include <stddef.h>
#include <stdint.h>

#include "openswarm/epuck_world_link.h"

/* The world's frames are 40 x 30 (docs/world.md); room for larger. */
#define WORLD_LINK_MAX_PIXELS (80u * 60u)

/* Opens QEMU's standard input and output (-semihosting-config
 * enable=on,target=native), or ends the run. */
void world_link_open(void);
void world_link_send(const void *data, size_t length);
/* The next input, and its frame's pixels (when it has one) into pixels
 * (WORLD_LINK_MAX_PIXELS of room). */
void world_link_read_input(epuck_world_input *in, uint16_t *pixels);
/* The link cannot go on: says why on the console, ends the run with
 * status 2, as the host build does. */
void world_link_broken(const char *why) __attribute__((noreturn));

#endif
