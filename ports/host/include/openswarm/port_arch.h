/* Host (POSIX) port: types the kernel needs. Threads are ucontexts on one
 * POSIX thread that plays the CPU; see ports/host/src/host_cpu.c. */
#ifndef OPENSWARM_PORT_ARCH_H
#define OPENSWARM_PORT_ARCH_H

#include <stddef.h>
#include <ucontext.h>

typedef struct port_context {
    ucontext_t uc;
    void (*entry)(void *);
    void *arg;
    void *stack; /* bounds, for AddressSanitizer's fiber switch annotations */
    size_t stack_size;
    void *fake_stack;
} port_context_t;

typedef int port_irq_state_t;

/* Room for libc, signal frames and sanitizer redzones on top of what a
 * thread asks for (sizes are chosen for the robots' 8/16-bit CPUs). */
#define PORT_STACK_EXTRA (128u * 1024u)
#define PORT_STACK_ALIGN 16u

/* A kernel starting again finds its stack pool holding no thread, though
 * the last kernel's threads may have been alive when it stopped (a host
 * test's kernel is powered off with its threads running): what
 * AddressSanitizer marked on their frames is forgotten before the pool is
 * painted, or the paint would be reported as a stack-buffer underflow
 * (host_context.c). */
void port_stack_pool_forget(void *pool, size_t bytes);
#define PORT_STACK_POOL_FORGET(pool, bytes) port_stack_pool_forget(pool, bytes)

/* Event ids the port reserves for its devices. */
#ifndef PORT_EVENT_COUNT
#define PORT_EVENT_COUNT 2
#endif

#endif
