/* ATOMIC_BLOCK in the native mode: the robot's interrupt mask, restored
 * (or set on) however the block is left. */
#ifndef OPENSWARM_NATIVE_UTIL_ATOMIC_H
#define OPENSWARM_NATIVE_UTIL_ATOMIC_H

#include "openswarm/port.h"

static inline void native_atomic_restore(const port_irq_state_t *state) { port_irq_restore(*state); }
static inline void native_atomic_on(const port_irq_state_t *state) {
    (void)state;
    port_irq_enable();
}

#define ATOMIC_RESTORESTATE \
    port_irq_state_t native_atomic_state __attribute__((cleanup(native_atomic_restore))) = port_irq_save()
#define ATOMIC_FORCEON \
    port_irq_state_t native_atomic_state __attribute__((cleanup(native_atomic_on))) = port_irq_save()
#define ATOMIC_BLOCK(kind) for (kind, native_atomic_once = 1; native_atomic_once; native_atomic_once = 0)

#endif
