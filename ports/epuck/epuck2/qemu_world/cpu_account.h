/* Where the e-puck2 image's CPU time goes in the world under QEMU, for the
 * OS's cost (docs/case-study.md, "The OS's cost, under QEMU"): TIM2 counts
 * QEMU's virtual time (1 GHz, exactly, with -icount), so the time between
 * two reads is the instructions run between them (8 ns each with -icount
 * shift=3) plus the time the CPU slept through. */
#ifndef EPUCK2_QEMU_WORLD_CPU_ACCOUNT_H
#define EPUCK2_QEMU_WORLD_CPU_ACCOUNT_H

#include <stdbool.h>
#include <stdint.h>

typedef enum cpu_account_kind {
    CPU_ASLEEP,  /* in WFI: the idle thread's sleep */
    CPU_LINK,    /* the world link's own work, SysTick stopped: not the robot's */
    CPU_SENSORS, /* the inputs delivered: the devices' interrupt-side work and their processors */
    CPU_KINDS
} cpu_account_kind;

/* Starts TIM2 and watches the idle thread's sleeps. */
void cpu_account_start(void);
/* The virtual time now (ns, wrapping): the start of an interval. */
uint32_t cpu_account_now(void);
/* The time from since to now, counted as kind. */
void cpu_account_add(cpu_account_kind kind, uint32_t since);
/* One console line: the virtual time run, and how much of the robot's was
 * spent asleep, on the sensors' deliveries and on everything else (the
 * kernel's ticks, scheduling, event dispatch, the handlers, the threads);
 * then the tick the robot ran with: none if kernel_ran is false (an image
 * that never starts its kernel, as the plain loop's), else the kernel's
 * build setting (tickless idle or periodic), for the benches to say. */
void cpu_account_report(bool kernel_ran);

#endif
