/* What an e-puck in the world shows, kept for the world link's answer:
 * the device layer's lower-layer outputs (src/epuck_board.h's set
 * functions) and the record that carries them, with the robot's time and
 * faults. Shared by both boards a world can run: the host build
 * (board_world.c) and the e-puck2 image under QEMU (epuck2/qemu_world). */
#ifndef EPUCK_WORLD_OUTPUTS_H
#define EPUCK_WORLD_OUTPUTS_H

#include "openswarm/epuck_world_link.h"

/* The answer to the world, filled on the robot's CPU (it reads the
 * kernel's clock and counters). */
void world_outputs_fill(epuck_world_output *out);
/* The kernel's loss counters, for the link's last message (on the robot's
 * CPU too). */
void world_outputs_losses(epuck_world_losses *out);
/* Its wheels and LEDs alone, as the device layer last set them: no call
 * into the kernel (the native board reads them from its work callback,
 * where the kernel's instrumented code must not run). */
void world_outputs_shown(epuck_world_output *out);

#endif
