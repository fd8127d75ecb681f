/* The e-puck's event ids, as the world's host build reserves them
 * (cmake/OpenSwarmKernel.cmake, board epuck_world: 16). */
#ifndef OPENSWARM_NATIVE_BOARD_ARCH_H
#define OPENSWARM_NATIVE_BOARD_ARCH_H

#define PORT_EVENT_COUNT 16

#endif
