/* Which handlers the kernel called (PORT_HANDLER_CALLED, port_arch.h), for
 * the simulator's warning of a handler subscribed and never called: each
 * function once, in the robot's native_io, which the simulator reads at
 * the end. A robot has few handlers and calls the same ones again and
 * again: a short list, searched from its start, finds them at once. */
#include "native_internal.h"

void native_handler_called(void (*function)(void)) {
    native_io *io = native_io_of_robot;
    uintptr_t f = (uintptr_t)function;
    for (unsigned i = 0; i < io->n_handlers_called; i++)
        if (io->handlers_called[i] == f) return;
    if (io->n_handlers_called < NATIVE_HANDLERS_SEEN)
        io->handlers_called[io->n_handlers_called++] = f;
    else
        io->handlers_called_full = 1;
}
