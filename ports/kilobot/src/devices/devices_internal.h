/* Shared by the Kilobot's device drivers and the port's tick: the calls
 * between them that applications do not make. */
#ifndef OPENSWARM_KILOBOT_DEVICES_INTERNAL_H
#define OPENSWARM_KILOBOT_DEVICES_INTERNAL_H

#include <stdint.h>

#include "openswarm/config.h"
#include "openswarm/kilobot.h"

/* motors.c. From now on, a motor at full power for more than limit_ms
 * drops to fallback (0: no limit); checked every 1 ms by the motors' tick
 * hook, which only these two set (NULL: no limit). */
void kilobot_motors_limit_full_power(uint16_t limit_ms, uint8_t fallback);
void kilobot_motors_unlimit(void);
extern void (*kilobot_motors_tick_hook)(void);

/* sensors.c: sampling due every 1 ms (NULL: none); called by the tick
 * interrupt. Set with interrupts masked; applications that never set it
 * pay nothing (see kilobot_tick_hook). */
extern void (*kilobot_sensors_tick_hook)(void);

/* port.c: one millisecond of the robot's time (the kernel's tick, then the
 * devices' and the tick hooks), in interrupt context. The IR driver calls it
 * for each millisecond a frame kept the tick interrupt masked. The tick is
 * Timer0 in CTC mode: KILOBOT_TICK_COUNTS counts of KILOBOT_TICK_PRESCALE
 * cycles. */
void kilobot_tick(void);
/* Does a hook want this tick? (One that is never set costs nothing: with
 * link-time optimisation its test goes.) */
static inline bool kilobot_tick_hooked(void) {
    return kilobot_motors_tick_hook != NULL || kilobot_sensors_tick_hook != NULL ||
           kilobot_tick_hook != NULL || kilobot_elapsed_hook != NULL;
}
/* Anything that needs every millisecond keeps the tick when the robot
 * idles: the tick hook, the motors' full-power limit, periodic sensor
 * readings (an elapsed hook takes the milliseconds slept at once). */
static inline bool kilobot_tick_needed(void) {
    return kilobot_tick_hook != NULL || kilobot_motors_tick_hook != NULL ||
           kilobot_sensors_tick_hook != NULL;
}
#define KILOBOT_TICK_PRESCALE 64u
#define KILOBOT_TICK_COUNTS (F_CPU / KILOBOT_TICK_PRESCALE / 1000u)

/* tickless_idle.c (OS_CFG_TICKLESS). If the robot sleeps with the tick
 * stopped, the tick again (its phase unchanged); the milliseconds slept
 * are credited by the next os_isr_enter, or when the idle system thread
 * wakes, whichever comes first. For an interrupt that cannot wait for the
 * kernel's bookkeeping (the IR receiver's, at a frame's first pulse);
 * every other interrupt's os_isr_enter does both at once. */
#if OS_CFG_TICKLESS
void kilobot_tickless_stop(void);
#else
static inline void kilobot_tickless_stop(void) {}
#endif

/* ir.c (the board's lower layer): start listening. */
void kilobot_ir_start(void);
/* ir_device.c: the counters (kilobot_ir_stats), each stopping at its top
 * (a wrapped one could read 0 after 65536 losses); a whole frame received,
 * given to the device in the receiver's interrupt. */
extern kilobot_ir_stats kilobot_ir_counters;
void kilobot_ir_count(uint16_t *counter);
void kilobot_ir_deliver(const kilobot_ir_rx *rx);

/* adc.c: start a conversion of input (KILOBOT_ADC_*), and wait for its
 * result. For the IR receiver, which starts one at a pulse and takes it at
 * the next, interrupts masked; everything else uses kilobot_adc_read.
 * Starting takes the ADC from a reader holding it, whose reading is then
 * -1 (busy), after its conversion ends (at most 104 us). */
void kilobot_adc_start(uint8_t input);
int16_t kilobot_adc_take(void);


#endif
