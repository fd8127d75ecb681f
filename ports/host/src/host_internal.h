/* Shared between the host port's files. */
#ifndef OPENSWARM_HOST_INTERNAL_H
#define OPENSWARM_HOST_INTERNAL_H

#include "openswarm/host.h"
#include "openswarm/port.h"

#include <signal.h>

/* The signal that plays the CPU's interrupt line. */
#define HOST_IRQ_SIGNAL SIGUSR1

void host_context_init_system(void);

#endif
