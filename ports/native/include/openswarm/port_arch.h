/* Native port: the kernel compiled for the host as one of many robots in
 * the simulator's process (openswarm/native_robot.h). A suspended thread is
 * its stack pointer, as on the robots; interrupts come from the robot's
 * virtual clock (src/native_cpu.c). */
#ifndef OPENSWARM_NATIVE_PORT_ARCH_H
#define OPENSWARM_NATIVE_PORT_ARCH_H

#include <stddef.h>
#include <stdint.h>

typedef struct port_context {
    void *sp;
    void (*entry)(void *); /* a new thread's, until it starts */
    void *arg;
} port_context_t;

typedef uint8_t port_irq_state_t; /* 1: interrupts were masked */

/* Host code needs more stack than the robot's: libc's printf, the
 * interrupts' frames and the work callback on 64-bit registers. Added to
 * every requested size; the pool lives beside the robot's RAM image
 * (PORT_STACK_POOL), and only the pages a thread touches cost memory. */
#define PORT_STACK_EXTRA 8192u
#define PORT_STACK_ALIGN 16u

/* The robot's stacks are its own memory, not part of the image the
 * simulator copies in and out (set at power-up: native_cpu.c). */
extern uint8_t *native_stack_pool;
#define PORT_STACK_POOL native_stack_pool

/* Each handler the kernel calls is noted for the simulator, which warns
 * of a subscribed handler never called (native_handlers.c). */
void native_handler_called(void (*function)(void));
#define PORT_HANDLER_CALLED(function) native_handler_called((void (*)(void))(function))

/* The board's facts (its event ids). */
#include "openswarm/board_arch.h"

/* Idle is always tickless: a sleeping robot costs the simulator nothing
 * until its next deadline or frame. */
#define PORT_TICKLESS_IDLE 1

#endif
