/* e-puck (dsPIC30F6014A, Microchip XC16) port: types the kernel needs.
 * A 16-bit machine: int and pointers are 16 bits, the stack grows UP
 * (W15 points at the next free word) and SPLIM bounds it in hardware. */
#ifndef OPENSWARM_PORT_ARCH_H
#define OPENSWARM_PORT_ARCH_H

#include <stdint.h>

/* A suspended thread is its stack pointer and its stack limit; its
 * registers are on its stack. switch.s and traps.s read the three fields
 * at byte offsets 0, 2 and 4 (port.c checks them). */
typedef struct port_context {
    uint16_t *sp;    /* W15: the word above its switch frame */
    uint16_t *splim; /* SPLIM: the highest word it may push to */
    uint16_t *base;  /* where its stack starts; NULL for the system thread */
} port_context_t;

typedef uint16_t port_irq_state_t; /* SR's IPL bits before masking */

/* Bytes every thread stack needs beyond its own frames: the switch frame
 * (return address + 23 registers: 50 bytes), an interrupt's (the CPU's 2
 * words + XC16's prologue for a handler that calls: W0-W7, RCOUNT,
 * PSVPAG, W14: about 26 bytes), the kernel's calls from os_isr_exit to
 * port_switch (estimated at 40: never measured, no XC16 here) and the
 * room above SPLIM a stack-error trap stacks into (DSPIC_TRAP_ROOM_BYTES,
 * 8). Added to every requested size. */
#define PORT_STACK_EXTRA 128u
#define PORT_STACK_ALIGN 2u /* W15 must stay even */

/* Event ids the board reserves: the e-puck's eight devices (epuck.h). */
#ifndef PORT_EVENT_COUNT
#define PORT_EVENT_COUNT 8
#endif

#endif
