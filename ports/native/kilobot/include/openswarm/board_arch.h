/* The Kilobot's event ids, as its port reserves them
 * (ports/kilobot/include/openswarm/port_arch.h). */
#ifndef OPENSWARM_NATIVE_BOARD_ARCH_H
#define OPENSWARM_NATIVE_BOARD_ARCH_H

#define PORT_EVENT_COUNT 8

#endif
