/* Two threads that never block keep the tick, tickless idle or not: the
 * time slice switches between them (avr.tickless_time, qemu.tickless_time). */
#ifndef TESTS_FIRMWARE_BUSY_THREADS_H
#define TESTS_FIRMWARE_BUSY_THREADS_H

#include <stdbool.h>
#include <stdint.h>

typedef struct busy_threads_result {
    uint32_t woke_at_ms; /* the kernel's time when the 200 ms sleep ended */
    uint32_t switches;   /* thread switches meanwhile */
    bool both_spun;      /* each spinner ran */
} busy_threads_result;

/* Starts two spinning threads (two slots of the pool, for good) and sleeps
 * 200 ms among them. */
busy_threads_result busy_threads_run(void);

#endif
