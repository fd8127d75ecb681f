/* The link between the world simulator and an e-puck controller running on
 * the host port (ports/epuck/host): the world starts one process per
 * e-puck and talks to it over the process's standard input and output,
 * one exchange per world step, in lockstep with the world's clock.
 *
 *   world -> robot: epuck_world_input, then, when frame_width is not 0,
 *                   frame_width * frame_height RGB565 pixels (row after
 *                   row, uint16_t each, little-endian)
 *   robot -> world: epuck_world_output, once it has applied the input and
 *                   run advance_ms milliseconds of its own time; after the
 *                   last (the answer to EPUCK_LINK_STOP), epuck_world_losses
 *
 * Every field is little-endian, packed as declared (no padding: each
 * struct's fields fall on their natural alignment). The robot's first
 * output comes before any input, right after its kernel started (time 0,
 * wheels 0): the world knows then that the process is up. */
#ifndef OPENSWARM_EPUCK_WORLD_LINK_H
#define OPENSWARM_EPUCK_WORLD_LINK_H

#include <stdint.h>

#define EPUCK_LINK_MAGIC 0x314B5045u /* "EPK1" */
#define EPUCK_LINK_SENSORS 8

enum epuck_link_flags {
    EPUCK_LINK_PROXIMITY = 1, /* proximity samples below are new: deliver them */
    EPUCK_LINK_STOP = 2       /* end the run: the robot answers once more and exits 0 */
};

typedef struct epuck_world_input {
    uint32_t magic;
    uint32_t advance_ms; /* run this long after applying the inputs (0: just answer) */
    uint16_t flags;      /* epuck_link_flags */
    uint16_t selector;   /* 0..15 */
    /* As the board's ADC takes them (epuck_proximity_samples): with the
     * emitters off, and at the end of their pulse. */
    uint16_t proximity_off[EPUCK_LINK_SENSORS];
    uint16_t proximity_pulsed[EPUCK_LINK_SENSORS];
    uint16_t frame_width, frame_height; /* 0 x 0: no new frame this step */
} epuck_world_input;

typedef struct epuck_world_output {
    uint32_t magic;
    uint32_t time_ms;            /* the robot's system time */
    int16_t wheel_left, wheel_right; /* steps/s the steppers were last set to */
    uint8_t ring_leds, body_led, front_led, rgb_leds;
    uint32_t faults;             /* kernel faults reported so far */
} epuck_world_output;

/* After its answer to EPUCK_LINK_STOP a controller with a kernel sends
 * its kernel's loss counters (openswarm/fault.h's sys_stats, its uint16_t
 * counters in order), then exits: the world ends the run with them as
 * warnings. A controller without a kernel sends none. */
#define EPUCK_LINK_LOSSES_MAGIC 0x4C4B5045u /* "EPKL" */
#define EPUCK_LINK_LOSS_COUNTERS 12
typedef struct epuck_world_losses {
    uint32_t magic;
    uint16_t counters[EPUCK_LINK_LOSS_COUNTERS];
} epuck_world_losses;

#endif
