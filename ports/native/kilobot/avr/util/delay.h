/* Busy waits in the native mode: the robot's clock advances by the wait,
 * and interrupts due meanwhile run, as on the robot; their time does not
 * count toward the wait, as avr-libc's loops count their own cycles. */
#ifndef OPENSWARM_NATIVE_UTIL_DELAY_H
#define OPENSWARM_NATIVE_UTIL_DELAY_H

#include <stdint.h>

#ifndef F_CPU
#error "F_CPU: the native Kilobot's build defines it (8000000UL)"
#endif

#ifdef __cplusplus
extern "C" {
#endif
void native_busy_loop(uint64_t cycles);
#ifdef __cplusplus
}
#endif

static inline void _delay_ms(double ms) { native_busy_loop((uint64_t)(ms * (F_CPU / 1000.0))); }
static inline void _delay_us(double us) { native_busy_loop((uint64_t)(us * (F_CPU / 1000000.0))); }
#define __builtin_avr_delay_cycles(n) native_busy_loop((uint64_t)(n))

#endif
