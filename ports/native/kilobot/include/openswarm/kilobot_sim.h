/* What a Kilobot firmware tells the simulator (the robot's
 * ports/kilobot/include/openswarm/kilobot_sim.h), in the native mode:
 * the same calls, straight to the robot's console and state. */
#ifndef OPENSWARM_KILOBOT_SIM_H
#define OPENSWARM_KILOBOT_SIM_H

#include <stdint.h>

#include <avr/interrupt.h>
#include <avr/io.h>
#include <avr/pgmspace.h>
#include <avr/sleep.h>

#ifdef __cplusplus
extern "C" {
#endif

/* One console character (a line ends with '\n'). */
void sim_putc(char c);
void sim_puts_P(const char *text);
void sim_put_uint(uint32_t v);
/* A kernel fault (a sys_fault and the thread's pid). */
void sim_fault(uint8_t fault, uint8_t pid);
/* A thread's name, for fault reports. */
void sim_thread_name(uint8_t pid, const char *name);
/* Stop the simulation with an exit status. */
void sim_exit(uint8_t status) __attribute__((noreturn));

#ifdef __cplusplus
}
#endif

#endif
