/* Kilobot (ATmega328P) port: types the kernel needs. */
#ifndef OPENSWARM_PORT_ARCH_H
#define OPENSWARM_PORT_ARCH_H

#include <stdint.h>

/* A suspended thread is its stack pointer: everything else is on its stack. */
typedef struct port_context {
    uint8_t *sp;
} port_context_t;

typedef uint8_t port_irq_state_t; /* SREG */

/* Bytes every thread stack needs beyond its own frames: an interrupt's
 * saved registers (tick ISR: 15 registers + SREG + return address) and
 * the switch frame (18 callee-saved registers + return address), with the
 * kernel's call chain between them. Added to every requested size. */
#define PORT_STACK_EXTRA 64u
#define PORT_STACK_ALIGN 1u

/* Tickless idle (OS_CFG_TICKLESS): port_idle_for stops the tick until the
 * kernel's next deadline (src/tickless_idle.c). */
#define PORT_TICKLESS_IDLE 1

/* Event ids the port reserves: LED, motors, IR received, IR to send,
 * light, voltage, temperature, and kilolib's transmit callbacks. */
#define PORT_EVENT_COUNT 8

#endif
