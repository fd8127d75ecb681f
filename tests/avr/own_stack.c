/* A context of the firmware's own on a stack in its variables, entered
 * with port_switch directly (as a coroutine library or the benchmark's raw
 * switch does): the simulator's stack watch does not know its bounds and
 * does not judge it, so the run passes (avr.own_stack); it failed as a main
 * stack overflow when the watch took any stack outside the kernel's pool
 * for one. */
#include <avr/interrupt.h>
#include <stdint.h>

#include "openswarm/kilobot_sim.h"
#include "openswarm/port.h"

static port_context_t main_context, own_context;
static uint8_t own_stack[128];
static volatile uint8_t turns;

static void own(void *arg) {
    (void)arg;
    for (;;) {
        volatile uint8_t frame[24]; /* some depth on its own stack */
        frame[0] = turns;
        turns = (uint8_t)(frame[0] + 1u);
        port_switch(&own_context, &main_context);
    }
}

int main(void) {
    cli();
    port_context_init(&own_context, own_stack, sizeof own_stack, own, NULL);
    for (uint8_t i = 0; i < 10; i++) {
        port_switch(&main_context, &own_context);
        cli(); /* the first entry to own enabled interrupts */
    }
    sim_exit(turns == 10 ? 0 : 1);
    return 0;
}
