/* Between the simulator and a native e-puck (ports/native/epuck): what
 * native_io.board points to. The step's sensors go in as the pipe mode's
 * link carries them (openswarm/epuck_world_link.h's epuck_world_input, its
 * frame in pixels), so both modes hand a controller the same inputs; the
 * board keeps what it shows in shown, current whenever the robot yields. */
#ifndef OPENSWARM_NATIVE_EPUCK_H
#define OPENSWARM_NATIVE_EPUCK_H

#include <stdint.h>

#include "openswarm/epuck_world_link.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The world's camera frame (sim/src/world/epuck_sensors.h: 40 x 30). */
#define NATIVE_EPUCK_MAX_PIXELS (40u * 30u)

typedef struct native_epuck_io {
    /* ---- set by the simulator ---- */
    uint16_t robot_id; /* robot_id(): its index in the world file */
    epuck_world_input input; /* the step's (delivered when native_io.board_inputs is set) */
    uint16_t pixels[NATIVE_EPUCK_MAX_PIXELS];
    /* ---- set by the robot: its wheels and LEDs (the simulator fills in
     * the time and the faults, which it knows) ---- */
    epuck_world_output shown;
} native_epuck_io;

#ifdef __cplusplus
}
#endif

#endif
