/* Between the overhead control (overhead_control.c) and its calibrating
 * hold (overhead_calibration.c). */
#ifndef OPENSWARM_KILOBOT_OVERHEAD_CONTROL_INTERNAL_H
#define OPENSWARM_KILOBOT_OVERHEAD_CONTROL_INTERNAL_H

#include "openswarm/kilobot.h"

#define OVERHEAD_TYPE_BYTE 9u
/* What a system message's action reads: data and type, not the CRC
 * (kilobot_ohc_message). */
#define OVERHEAD_MESSAGE_BYTES 10u
/* A restart that holds: this, with the hold's message type in its low byte. */
#define OVERHEAD_HOLD_MARK 0x4800u

/* The held robot calibrates from now on, beginning with frame (a CALIB or
 * READUID): before the kernel starts. */
void overhead_calibration_start(const uint8_t *frame);
/* A system message while calibrating, in the IR interrupt. */
void overhead_calibration_take(const uint8_t *frame);

#endif
