/* Shared by the native port's files: the robot's clock, its contexts, its
 * link to the simulator, and what the board (ports/native/<robot>)
 * supplies. Not part of the API apps see. */
#ifndef OPENSWARM_NATIVE_INTERNAL_H
#define OPENSWARM_NATIVE_INTERNAL_H

#include <stddef.h>
#include <stdint.h>

#include "openswarm/native_robot.h"
#include "openswarm/port.h"

/* The robot's CPU cycles charged for each basic block of its compiled code
 * (the work callback), a measured average of the AVR's (docs/world.md,
 * "Native mode": how it was measured, and what it means for timing). */
#ifndef NATIVE_CYCLES_PER_BLOCK
#define NATIVE_CYCLES_PER_BLOCK 19u
#endif

/* native_cpu.c: the clock (the robot's own cycles since power-up) and the
 * window the simulator gave. */
extern uint64_t native_now;
void native_window(uint64_t end);
void native_due_again(void);
/* Work done outside the instrumented code (a frame's transmission, a
 * conversion): the clock advances, interrupts due meanwhile come after. */
void native_spend(uint64_t cycles);
/* Waits with interrupts as they are: for hardware that runs on by itself
 * (a UART character, a conversion: the interrupts' time counts toward it),
 * and a loop that counts its own cycles (_delay_ms: it does not). Holding
 * interrupts back instead lost the frames that began meanwhile: robots
 * that printed what they heard missed the next frame. */
void native_wait_for_hardware(uint64_t cycles);
void native_busy_loop(uint64_t cycles);
uint8_t native_irq_masked(void);
void native_tickless_wake(void);

/* native_context.c, native_switch.S */
void native_switch(void **save_sp, void *to_sp);
void native_context_start(void);
void native_call_on_stack(void (*fn)(void), void *sp);
/* A fresh context on [stack, stack + size) whose first switch runs entry(arg). */
void *native_context_frame(void *stack, size_t size, void (*entry)(void *), void *arg);
void native_context_returned(void);

/* native_robot.c: the link to the simulator. Main's stack: host code
 * (libc's printf) needs more than the robot's 2 KB; untouched pages cost
 * nothing. */
#define NATIVE_MAIN_STACK_BYTES (64u * 1024u)
/* The robot's native_io (the simulator's memory). */
extern native_io *native_io_of_robot;
/* Back to the simulator; returns when it runs the robot again. */
void native_yield(void);
/* The robot's own random sequence (the board's noise and jitter). */
uint64_t native_random(void);
/* Until index < room: a full outbound list waits for the simulator to empty it. */
void native_make_room(const unsigned *count, unsigned room);
/* The robot is over for good (main returned, sim_exit). */
void native_stop(uint8_t status) __attribute__((noreturn));
/* The robot leaves its program: to be booted afresh (RESTART) or for the
 * bootloader. */
void native_leave(uint8_t state) __attribute__((noreturn));

/* The board: its clock rate, its tick, the interrupts it raises. */
#define NATIVE_CYCLES_PER_TICK (NATIVE_CPU_HZ / 1000u)
void native_board_tick(void);
int native_board_tick_hooked(void);
int native_board_tick_needed(void);
void native_board_elapsed(uint16_t ms);
/* The receiver's interrupt: the inbox's first frame has arrived. It
 * counts the frames it took in (their distance takes the ADC). */
void native_ir_interrupt(void);
extern uint32_t native_ir_receptions;
/* The board's interrupt for the inputs the simulator set in its native_io
 * (board, board_inputs): called with board_inputs cleared. */
void native_board_inputs(void);
/* What the board's outputs show now, reported to the simulator if it
 * changed: 0 when its list had no room (the simulator empties it when the
 * robot yields). */
int native_outputs_report(void);
/* At power-up, before main. */
void native_board_power_up(void);

#endif
