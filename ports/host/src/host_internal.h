/* Shared between the host port's files. */
#ifndef OPENSWARM_HOST_INTERNAL_H
#define OPENSWARM_HOST_INTERNAL_H

#include "openswarm/host.h"
#include "openswarm/port.h"

#include <signal.h>
#include <stdbool.h>

/* The signal that plays the CPU's interrupt line. */
#define HOST_IRQ_SIGNAL SIGUSR1

void host_context_init_system(void);
bool host_context_in_system_thread(void);
/* Called when the system thread first switches or idles. */
void host_cpu_note_scheduling(void);

#endif
