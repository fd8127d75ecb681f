/* robot.h's robot_id and robot_console_init for an e-puck of the world:
 * the world starts each robot's process with its index in the world file
 * in OPENSWARM_ROBOT_ID (sim/src/world/epuck_link.c); printf already goes
 * to the world's standard error, a line at a time (link_take_stdout). */
#include <stdlib.h>

#include "openswarm/robot.h"

uint16_t epuck_robot_id(void) {
    const char *given = getenv("OPENSWARM_ROBOT_ID");
    return given == NULL ? 0u : (uint16_t)strtoul(given, NULL, 10);
}

void epuck_console_init(void) {}
