/* The e-puck board on the host port, as the world link drives it
 * (world_link_main.c). Each function is called from the link's thread, not
 * the simulated CPU: inputs become interrupts on the CPU, and the outputs
 * are read there too, so the kernel's state is only ever touched by the
 * CPU. */
#ifndef EPUCK_BOARD_WORLD_H
#define EPUCK_BOARD_WORLD_H

#include <stdint.h>

#include "openswarm/epuck.h"
#include "openswarm/epuck_world_link.h"

/* Deliver the selector's position, when it differs from the last one
 * delivered (the first is always delivered). */
void board_world_deliver_selector(uint8_t position);
void board_world_deliver_proximity(const epuck_proximity_samples *samples);
/* The pixels need to live only until this returns: the camera's
 * classifier runs in the interrupt. */
void board_world_deliver_frame(const uint16_t *pixels, uint16_t width, uint16_t height);

/* The robot's outputs, its time and its faults, as one snapshot. */
void board_world_report(epuck_world_output *out);
/* The kernel's loss counters, for the link's last message. */
void board_world_losses(epuck_world_losses *out);

#endif
