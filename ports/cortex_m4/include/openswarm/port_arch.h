/* Cortex-M4F port (ARMv7E-M with the single-precision FPU): types the
 * kernel needs. See ports/cortex_m4/README.md for the interrupt model. */
#ifndef OPENSWARM_PORT_ARCH_H
#define OPENSWARM_PORT_ARCH_H

#include <stdint.h>

/* A suspended thread is its process stack pointer: its callee-saved
 * registers (and, if it used the FPU, s16-s31) are on its stack. */
typedef struct port_context {
    uint32_t *sp;
} port_context_t;

typedef uint32_t port_irq_state_t; /* BASEPRI */

/* Bytes every thread stack needs beyond its own frames: the switch frame
 * (10 words + s16-s31: 104 bytes), an interrupt's extended exception frame
 * (26 words + alignment: 108 bytes), the interrupt epilogue's call into
 * the kernel (os_isr_exit: about 120 bytes measured, see README) and the
 * return's SVC frame (32 bytes). */
#define PORT_STACK_EXTRA 384u
#define PORT_STACK_ALIGN 8u /* AAPCS: 8-byte aligned at every call */

/* Tickless idle (OS_CFG_TICKLESS, on by default: port_config.h): SysTick
 * stretches a period over the ticks until the kernel's next deadline
 * (src/tickless_idle.c). */
#define PORT_TICKLESS_IDLE 1

/* Event ids the board reserves for its devices (the e-puck's: epuck.h). */
#ifndef PORT_EVENT_COUNT
#define PORT_EVENT_COUNT 16
#endif

#endif
