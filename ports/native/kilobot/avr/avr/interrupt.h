/* Interrupts in the native mode: the robot's own mask (ports/native). */
#ifndef OPENSWARM_NATIVE_AVR_INTERRUPT_H
#define OPENSWARM_NATIVE_AVR_INTERRUPT_H

#include "openswarm/port.h"

#define cli() port_irq_disable()
#define sei() port_irq_enable()
/* A handler of the program's own has no vector to run from here: the
 * board's interrupts are the kernel's. */
#define ISR(vector, ...)                                                                      \
    _Static_assert(0, "ISR(" #vector "): a program's own interrupt handlers run in the exact " \
                      "mode only (openswarm run without --native)");                           \
    static void native_isr_##vector(void)

#endif
