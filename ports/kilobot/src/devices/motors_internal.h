/* Shared by the motor driver and its processors. */
#ifndef OPENSWARM_KILOBOT_MOTORS_INTERNAL_H
#define OPENSWARM_KILOBOT_MOTORS_INTERNAL_H

#include <stdint.h>

/* From now on, a motor at full power for more than limit_ms drops to
 * fallback (checked every 1 ms by kilobot_motors_tick). */
void kilobot_motors_limit_full_power(uint16_t limit_ms, uint8_t fallback);
/* Called every 1 ms from the tick interrupt. */
void kilobot_motors_tick(void);

/* ir.c: start listening (analog comparator to Timer1 input capture). */
void kilobot_ir_start(void);

#endif
