/* Thread slots: creation, termination, reaping, and lookup by pid. */
#include "kernel_internal.h"

#define SLOT_OF(pid) ((uint8_t)((pid)&0x0Fu))
#define GENERATION_OF(pid) ((uint8_t)((pid) >> 4))

sys_tcb *os_thread_of(sys_pid pid) {
    uint8_t slot = SLOT_OF(pid);
    if (slot >= OS_CFG_MAX_THREADS) return NULL;
    sys_tcb *t = &os.threads[slot];
    if (t->state == OS_SLOT_FREE || t->pid != pid) return NULL;
    return t;
}

static sys_tcb *free_slot(void) {
    for (uint8_t i = 1; i < OS_CFG_MAX_THREADS; i++)
        if (os.threads[i].state == OS_SLOT_FREE) return &os.threads[i];
    return NULL;
}

sys_status Sys_Start_Process_Ex(sys_process_fn fn, void *arg, uint16_t stack_bytes,
                                uint8_t priority, sys_pid *pid) {
    if (fn == NULL) return SYS_E_INVALID;
    if (stack_bytes == 0) stack_bytes = OS_CFG_DEFAULT_STACK_BYTES;
    port_irq_state_t s = port_irq_save();
    sys_tcb *t = free_slot();
    size_t size = t != NULL ? os_stack_alloc(t, stack_bytes) : 0;
    if (size == 0) {
        os_count(t == NULL ? &os_stats.process_pool_full : &os_stats.stack_pool_full);
        port_irq_restore(s);
        return SYS_E_POOL_FULL;
    }
    t->priority = priority;
    t->state = SYS_PROCESS_NEW; /* its wait is NULL: os_terminate cleared it */
    /* pid = slot | generation << 4; the generation was bumped at reaping. */
    t->pid = (sys_pid)((t->pid & 0xF0u) | (uint8_t)(t - os.threads));
    port_context_init(&t->ctx, t->stack, size, fn, arg);
    os_make_ready(t);
    if (pid != NULL) *pid = t->pid;
    os_schedule(); /* a higher priority may preempt a thread that starts one */
    port_irq_restore(s);
    return SYS_OK;
}

/* Sys_Start_Process takes the paper's argument-less thread function; it
 * travels through the void * argument (all our targets have function and
 * data pointers of one size). */
typedef union plain_fn {
    void (*fn)(void);
    void *erased;
} plain_fn;

static void run_plain(void *arg) {
    plain_fn f;
    f.erased = arg;
    f.fn();
}

sys_pid Sys_Start_Process(void (*fn)(void)) {
    sys_pid pid = SYS_PID_NONE;
    if (fn == NULL) return SYS_PID_NONE;
    plain_fn f;
    f.fn = fn;
    return Sys_Start_Process_Ex(run_plain, f.erased, 0, SYS_PRIORITY_DEFAULT, &pid) == SYS_OK
               ? pid
               : SYS_PID_NONE;
}

/* What every ending does, once t is in no ready list and waits for
 * nothing (as the running thread is not and does not: a thread that
 * returns needs no more). */
static void make_zombie(sys_tcb *t) {
    if (t == os.current && os.lock_depth != 0) {
        os.lock_depth = 0;
        os_count(&os_stats.critical_leaks);
        os_fault(SYS_FAULT_CRITICAL_LEAK, t->pid);
    }
    os_subscriptions_remove_thread(t->pid);
    t->state = SYS_PROCESS_ZOMBIE;
    os.system_work |= OS_WORK_REAP;
    os.reconsider = true;
}

void os_terminate(sys_tcb *t) {
    if (t == os.preempted)
        os.preempted = NULL;
    else if (t->state == SYS_PROCESS_READY || t->state == SYS_PROCESS_NEW)
        os_ready_remove(t);
    os_wait_abandon(t);
    make_zombie(t);
}

/* Runs in the system thread, never on the stack it frees. */
void os_reap_zombies(void) {
    for (uint8_t i = 1; i < OS_CFG_MAX_THREADS; i++) {
        sys_tcb *t = &os.threads[i];
        if (t->state != SYS_PROCESS_ZOMBIE) continue;
        os_stack_free(t); /* for os_stack_alloc */
        t->state = OS_SLOT_FREE;
        t->pid = (sys_pid)(t->pid + 0x10u); /* next generation */
        /* 0xFF means "none": only slot 15, with 16 threads, could get it */
        if (OS_CFG_MAX_THREADS == 16 && t->pid == SYS_PID_NONE) t->pid = (sys_pid)(t->pid + 0x10u);
    }
    os.system_work &= (uint8_t)~OS_WORK_REAP;
}

sys_status Sys_Kill_Process(sys_pid pid) {
    port_irq_state_t s = port_irq_save();
    sys_tcb *t = os_thread_of(pid);
    if (t == NULL || t == OS_SYSTEM || t->state == SYS_PROCESS_ZOMBIE) {
        port_irq_restore(s);
        return SYS_E_INVALID;
    }
    os_terminate(t);
    os_schedule(); /* does not return if t is the caller */
    port_irq_restore(s);
    return SYS_OK;
}

void os_thread_exit(void) {
    port_irq_disable();
    make_zombie(os.current); /* running: neither ready, preempted nor waiting */
    os_schedule();
    for (;;) {
        /* unreachable: a zombie is never scheduled again */
    }
}

void os_thread_fault(uint8_t fault) {
    port_irq_disable();
    os_count(&os_stats.cpu_faults);
    os_fault((sys_fault)fault, os.current->pid);
    os_thread_exit();
}

sys_status Sys_Yield(void) {
    /* A thread's, outside any critical section: one test of both depths. */
    if ((os.isr_depth | os.lock_depth) != 0 || os.current == OS_SYSTEM) return SYS_E_CONTEXT;
    port_irq_state_t s = port_irq_save();
    os_yield();
    port_irq_restore(s);
    return SYS_OK;
}

sys_status Sys_Start_CriticalSection(void) {
    if (os.isr_depth != 0) return SYS_E_CONTEXT;
    port_irq_state_t s = port_irq_save();
    os.lock_depth++;
    port_irq_restore(s);
    return SYS_OK;
}

sys_status Sys_End_CriticalSection(void) {
    if (os.isr_depth != 0) return SYS_E_CONTEXT;
    port_irq_state_t s = port_irq_save();
    if (os.lock_depth == 0) {
        port_irq_restore(s);
        return SYS_E_INVALID;
    }
    if (--os.lock_depth == 0) os_schedule(); /* run what was postponed */
    port_irq_restore(s);
    return SYS_OK;
}

sys_pid Sys_Get_ProcessID(void) { return os.current->pid; }

sys_status Sys_Get_ProcessState(sys_pid pid, sys_process_state *state) {
    port_irq_state_t s = port_irq_save();
    sys_tcb *t = os_thread_of(pid);
    /* The current context runs: the system thread too while its handlers
     * run on behalf of a thread (its record then says READY). */
    if (t != NULL && state != NULL) *state = t == os.current ? SYS_PROCESS_RUNNING : (sys_process_state)t->state;
    port_irq_restore(s);
    return t != NULL ? SYS_OK : SYS_E_INVALID;
}

sys_status Sys_Set_Priority(sys_pid pid, uint8_t priority) {
    /* The system thread is never queued: a priority would put it in the
     * ready list, among the threads it schedules. */
    if (pid == SYS_PID_SYSTEM) return SYS_E_INVALID;
    port_irq_state_t s = port_irq_save();
    sys_tcb *t = os_thread_of(pid);
    if (t == NULL || t->state == SYS_PROCESS_ZOMBIE) {
        port_irq_restore(s);
        return SYS_E_INVALID;
    }
    t->priority = priority;
    os.reconsider = true; /* the running thread's may have dropped */
    if (t->state == SYS_PROCESS_READY || t->state == SYS_PROCESS_NEW) {
        if (t != os.preempted) {
            os_ready_remove(t); /* re-queue at the place its new priority earns */
            os_make_ready(t);
        }
    }
    os_schedule();
    port_irq_restore(s);
    return SYS_OK;
}

uint32_t Sys_Get_SwitchCount(void) {
    port_irq_state_t s = port_irq_save();
    uint32_t n = 0;
    for (unsigned i = sizeof os.switches; i-- != 0;) n = n << 8 | os.switches[i];
    port_irq_restore(s);
    return n;
}
