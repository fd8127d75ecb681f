/* Thread contexts on the host: ucontexts on the CPU thread, with stacks
 * from the kernel's pool. Switching may happen inside the interrupt signal
 * handler, as a preemptive switch does on a robot. */
#define _GNU_SOURCE
#include "host_internal.h"

#include <pthread.h>
#include <signal.h>
#include <string.h>

#if defined(__SANITIZE_ADDRESS__)
#define HOST_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define HOST_ASAN 1
#endif
#endif

#ifdef HOST_ASAN
#include <sanitizer/asan_interface.h>
#include <sanitizer/common_interface_defs.h>
#endif

static port_context_t *running;      /* context on the CPU now */
static port_context_t system_bounds; /* the CPU thread's own stack */

void host_context_init_system(void) {
    pthread_attr_t attr;
    memset(&system_bounds, 0, sizeof system_bounds);
    if (pthread_getattr_np(pthread_self(), &attr) == 0) {
        pthread_attr_getstack(&attr, &system_bounds.stack, &system_bounds.stack_size);
        pthread_attr_destroy(&attr);
    }
    running = NULL;
}

static bool on_system_stack; /* handlers dispatched on behalf of the system thread */

/* The system thread's context is the only one port_context_init never saw. */
bool host_context_in_system_thread(void) {
    return on_system_stack || running == NULL || running->entry == NULL;
}

/* Host stacks are large: the handlers run on the running context's stack,
 * but count as the system thread's. */
void port_call_on_system_stack(port_context_t *system, void (*fn)(void)) {
    (void)system;
    bool outer = on_system_stack;
    on_system_stack = true;
    fn();
    on_system_stack = outer;
}

static void thread_start(void) {
#ifdef HOST_ASAN
    __sanitizer_finish_switch_fiber(NULL, NULL, NULL);
#endif
    port_context_t *self = running;
    port_irq_enable();
    self->entry(self->arg);
    os_thread_exit();
}

void port_stack_pool_forget(void *pool, size_t bytes) {
#ifdef HOST_ASAN
    ASAN_UNPOISON_MEMORY_REGION(pool, bytes);
#else
    (void)pool;
    (void)bytes;
#endif
}

void port_context_init(port_context_t *ctx, void *stack, size_t size, void (*entry)(void *),
                       void *arg) {
    memset(ctx, 0, sizeof *ctx);
#ifdef HOST_ASAN
    ASAN_UNPOISON_MEMORY_REGION(stack, size); /* frames of a reaped thread */
#endif
    getcontext(&ctx->uc);
    ctx->uc.uc_stack.ss_sp = stack;
    ctx->uc.uc_stack.ss_size = size;
    ctx->uc.uc_link = NULL;
    sigdelset(&ctx->uc.uc_sigmask, HOST_IRQ_SIGNAL); /* may be created from an ISR */
    ctx->entry = entry;
    ctx->arg = arg;
    ctx->stack = stack;
    ctx->stack_size = size;
    makecontext(&ctx->uc, thread_start, 0);
}

void port_switch(port_context_t *from, port_context_t *to) {
    if (to->stack == NULL) { /* the system thread runs on the CPU thread's stack */
        to->stack = system_bounds.stack;
        to->stack_size = system_bounds.stack_size;
    }
    running = to;
    host_cpu_note_scheduling();
#ifdef HOST_ASAN
    __sanitizer_start_switch_fiber(&from->fake_stack, to->stack, to->stack_size);
#endif
    swapcontext(&from->uc, &to->uc);
#ifdef HOST_ASAN
    __sanitizer_finish_switch_fiber(from->fake_stack, NULL, NULL);
#endif
}
