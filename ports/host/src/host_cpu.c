/* The host port's CPU: interrupt masking, interrupt delivery, idling, and
 * the driver API of openswarm/host.h.
 *
 * The kernel runs on one POSIX thread (the CPU). The interrupt mask is a
 * flag of that thread, like the AVR's I bit. Whoever raises an interrupt
 * (the test driver, the real-time timer) marks it pending and sends the CPU
 * a signal. If interrupts are enabled, the signal handler services it on
 * the stack of whatever thread runs, and may switch threads from there;
 * if they are masked, the handler leaves it pending and it is serviced the
 * moment the kernel unmasks them, exactly like a pending AVR interrupt.
 *
 * For the driver to know when an interrupt's effects are over, the CPU
 * acknowledges the sequence number of the last interrupt raised before it
 * found nothing pending, each time it is back in thread code or idle. */
#define _GNU_SOURCE
#include "host_internal.h"

#include <errno.h>
#include <pthread.h>
#include <semaphore.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "openswarm/kernel.h"

static atomic_int irq_masked = 1;
static atomic_uint pending_ticks;
static atomic_bool pending_isr;
static atomic_bool pending_stop;
static void (*isr_fn)(void *);
static void *isr_arg;

static atomic_uint raised; /* sequence number of the last interrupt raised */
static atomic_uint acked;  /* last one whose effects are over */
static atomic_bool cpu_idle;
static atomic_bool scheduling; /* the system thread has begun to run threads */
static sem_t wakeup;   /* posted on every raise, for the idle CPU */
static sem_t progress; /* posted on every acknowledgement, for the driver */

static pthread_t cpu;
static atomic_bool cpu_alive;
static host_clock clock_mode = HOST_CLOCK_REALTIME;
static pthread_t timer;
static atomic_bool timer_running;
static pthread_mutex_t driver_lock = PTHREAD_MUTEX_INITIALIZER;
static void (*idle_window_hook)(void); /* tests only (host.h) */

static bool anything_pending(void) {
    return atomic_load(&pending_ticks) != 0 || atomic_load(&pending_isr) ||
           atomic_load(&pending_stop);
}

/* Service one batch of pending interrupts; false if there was none. */
static bool service_batch(void) {
    unsigned ticks = atomic_exchange(&pending_ticks, 0);
    bool isr = atomic_exchange(&pending_isr, false);
    bool stop = atomic_exchange(&pending_stop, false);
    if (ticks == 0 && !isr && !stop) return false;
    /* A lone tick takes a robot's way: quiet, or the end of a slice that
     * rotates at once (which may switch threads: we continue when resumed). */
    if (ticks == 1 && !isr && !stop && os_tick_quiet()) return true;
    os_isr_enter();
    while (ticks-- != 0)
        if (!os_tick_quiet()) os_tick(); /* the quiet way when it can, as a robot's tick */
    if (isr) isr_fn(isr_arg);
    if (stop) Sys_Stop_Kernel();
    os_isr_exit(); /* may switch threads; we continue when resumed */
    return true;
}

/* With interrupts masked: service until nothing is pending. Back in a
 * user thread, acknowledge everything raised so far; the system thread does
 * not, since it is still busy with the interrupts' consequences (handlers)
 * and acknowledges when it idles. */
static void service_all(void) {
    for (;;) {
        unsigned seq = atomic_load(&raised);
        if (!service_batch()) {
            if (!host_context_in_system_thread()) {
                atomic_store(&acked, seq);
                sem_post(&progress);
            }
            return;
        }
    }
}

static void on_irq_signal(int sig) {
    (void)sig;
    if (atomic_load(&irq_masked)) return; /* serviced when unmasked */
    int saved_errno = errno;
    atomic_store(&irq_masked, 1);
    service_all();
    atomic_store(&irq_masked, 0);
    errno = saved_errno;
}

port_irq_state_t port_irq_save(void) { return atomic_exchange(&irq_masked, 1); }

void port_irq_disable(void) { atomic_store(&irq_masked, 1); }

void port_irq_enable(void) {
    if (!atomic_load(&irq_masked)) return;
    service_all();
    atomic_store(&irq_masked, 0);
    /* An interrupt raised between the last check and the unmask found the
     * mask set and left its work pending: take it now. */
    while (anything_pending()) {
        atomic_store(&irq_masked, 1);
        service_all();
        atomic_store(&irq_masked, 0);
    }
}

void port_irq_restore(port_irq_state_t state) {
    if (!state) port_irq_enable();
}

void host_cpu_note_scheduling(void) { atomic_store(&scheduling, true); }

void port_idle(void) {
    host_cpu_note_scheduling();
    for (;;) {
        /* Only what was raised before the look for pending work may be
         * acknowledged: an interrupt raised after the look was not
         * serviced (its pending flag is set before its number, raise_irq's
         * callers), and acknowledging it let host_cpu_interrupt return
         * before its ISR ran. */
        unsigned seq = atomic_load(&raised);
        if (anything_pending()) {
            service_all();
            return;
        }
        if (idle_window_hook != NULL) idle_window_hook();
        atomic_store(&acked, seq);
        atomic_store(&cpu_idle, true);
        sem_post(&progress);
        if (!anything_pending()) {
            while (sem_wait(&wakeup) != 0 && errno == EINTR) {
            }
        }
        atomic_store(&cpu_idle, false);
    }
}

static pthread_once_t semaphores_once = PTHREAD_ONCE_INIT;

static void init_semaphores(void) {
    sem_init(&wakeup, 0, 0);
    sem_init(&progress, 0, 0);
}

static void drain(sem_t *sem) {
    while (sem_trywait(sem) == 0) {
    }
}

void port_init(void) {
    pthread_once(&semaphores_once, init_semaphores);
    drain(&wakeup);
    drain(&progress);
    cpu = pthread_self();
    atomic_store(&irq_masked, 1);
    atomic_store(&pending_ticks, 0);
    atomic_store(&pending_isr, false);
    atomic_store(&pending_stop, false);
    atomic_store(&raised, 0);
    atomic_store(&acked, 0);
    atomic_store(&cpu_idle, false);
    atomic_store(&scheduling, false);
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_irq_signal;
    sigemptyset(&sa.sa_mask);
    sigaction(HOST_IRQ_SIGNAL, &sa, NULL);
    sigset_t irq;
    sigemptyset(&irq);
    sigaddset(&irq, HOST_IRQ_SIGNAL);
    pthread_sigmask(SIG_UNBLOCK, &irq, NULL);
    host_context_init_system();
    atomic_store(&cpu_alive, true);
}

/* ---- raising interrupts (any thread but the CPU) ---- */

static unsigned raise_irq(void) {
    unsigned seq = atomic_fetch_add(&raised, 1) + 1;
    sem_post(&wakeup);
    /* An idle CPU is woken by the post and services what is pending
     * before it sleeps again (port_idle): only a running one needs the
     * signal to be interrupted. */
    if (atomic_load(&cpu_alive) && !atomic_load(&cpu_idle)) pthread_kill(cpu, HOST_IRQ_SIGNAL);
    return seq;
}

/* For sem_timedwait: now plus ms of wall-clock time. */
static struct timespec deadline_in(uint32_t ms) {
    struct timespec t;
    clock_gettime(CLOCK_REALTIME, &t);
    t.tv_sec += ms / 1000;
    t.tv_nsec += (long)(ms % 1000) * 1000000L;
    if (t.tv_nsec >= 1000000000L) {
        t.tv_nsec -= 1000000000L;
        t.tv_sec++;
    }
    return t;
}

static void wait_ack(unsigned seq) {
    struct timespec deadline = deadline_in(10000);
    while ((int)(atomic_load(&acked) - seq) < 0) {
        if (sem_timedwait(&progress, &deadline) != 0 && errno == ETIMEDOUT) {
            fprintf(stderr, "host port: the CPU did not service interrupt %u within 10 s "
                            "(a thread keeps interrupts masked?)\n", seq);
            abort();
        }
    }
}

static void *timer_main(void *unused) {
    (void)unused;
    struct timespec next;
    clock_gettime(CLOCK_MONOTONIC, &next);
    while (atomic_load(&timer_running)) {
        next.tv_nsec += 1000000;
        if (next.tv_nsec >= 1000000000) {
            next.tv_nsec -= 1000000000;
            next.tv_sec++;
        }
        clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &next, NULL);
        atomic_fetch_add(&pending_ticks, 1);
        raise_irq();
    }
    return NULL;
}

void host_set_clock(host_clock clock) { clock_mode = clock; }

void host_cpu_set_idle_window_hook(void (*hook)(void)) { idle_window_hook = hook; }

void port_tick_start(void) {
    if (clock_mode != HOST_CLOCK_REALTIME || atomic_load(&timer_running)) return;
    atomic_store(&timer_running, true);
    pthread_create(&timer, NULL, timer_main, NULL);
}

static void stop_timer(void) {
    if (atomic_exchange(&timer_running, false)) pthread_join(timer, NULL);
}

/* The CPU is idle with nothing pending: every thread is blocked. */
static bool cpu_settled(void) {
    return atomic_load(&cpu_idle) && atomic_load(&acked) == atomic_load(&raised) &&
           !anything_pending();
}

/* Between two manual ticks the threads get a moment of CPU time: without
 * it, back-to-back interrupts would be delivered before a preempted thread
 * executes a single instruction. The moment ends early when the CPU goes
 * idle (no thread wants more), which is most ticks of an event-driven app:
 * a world of e-pucks runs that much faster. Results never depend on its
 * length. */
static void let_threads_run(void) {
    struct timespec deadline;
    clock_gettime(CLOCK_REALTIME, &deadline);
    deadline.tv_nsec += 20000;
    if (deadline.tv_nsec >= 1000000000L) {
        deadline.tv_nsec -= 1000000000L;
        deadline.tv_sec++;
    }
    while (!cpu_settled())
        if (sem_timedwait(&progress, &deadline) != 0 && errno == ETIMEDOUT) return;
}

void host_cpu_advance(uint32_t ms) {
    pthread_mutex_lock(&driver_lock);
    for (uint32_t i = 0; i < ms; i++) {
        atomic_fetch_add(&pending_ticks, 1);
        wait_ack(raise_irq());
        let_threads_run();
    }
    pthread_mutex_unlock(&driver_lock);
}

void host_cpu_interrupt(void (*isr)(void *), void *arg) {
    pthread_mutex_lock(&driver_lock);
    isr_fn = isr;
    isr_arg = arg;
    atomic_store(&pending_isr, true);
    wait_ack(raise_irq());
    pthread_mutex_unlock(&driver_lock);
}

bool host_cpu_wait_idle(uint32_t timeout_ms) {
    struct timespec deadline = deadline_in(timeout_ms);
    for (;;) {
        if (cpu_settled()) return true;
        if (sem_timedwait(&progress, &deadline) != 0 && errno == ETIMEDOUT) return false;
    }
}

/* The CPU runs either the fixed start-up around a setup function or an
 * app's own main, which starts the kernel itself. */
static void (*cpu_setup)(void);
static int (*cpu_app_main)(void);

static void *cpu_main(void *unused) {
    (void)unused;
    if (cpu_app_main != NULL) {
        cpu_app_main();
        return NULL;
    }
    Sys_Init_Kernel();
    cpu_setup();
    Sys_Start_Kernel();
    Sys_Run_SystemThread();
    return NULL;
}

static void power_on(host_clock clock) {
    clock_mode = clock;
    atomic_store(&cpu_alive, false);
    atomic_store(&acked, 0);
    atomic_store(&raised, 0);
    pthread_attr_t attr;
    pthread_attr_init(&attr);
    pthread_attr_setstacksize(&attr, 1024 * 1024);
    sigset_t irq;
    sigemptyset(&irq);
    sigaddset(&irq, HOST_IRQ_SIGNAL);
    /* Only the CPU takes the interrupt signal: the driver blocks it. */
    pthread_sigmask(SIG_BLOCK, &irq, NULL);
    pthread_t t;
    pthread_create(&t, &attr, cpu_main, NULL);
    pthread_attr_destroy(&attr);
    /* Return once the system thread runs threads, so that the caller's
     * first tick finds them running rather than the kernel starting up. */
    while (!atomic_load(&cpu_alive) || !atomic_load(&scheduling)) sched_yield();
}

void host_cpu_start(host_clock clock, void (*setup)(void)) {
    cpu_setup = setup;
    cpu_app_main = NULL;
    power_on(clock);
}

void host_cpu_start_main(host_clock clock, int (*app_main)(void)) {
    cpu_app_main = app_main;
    power_on(clock);
}

void host_cpu_stop(void) {
    stop_timer();
    pthread_mutex_lock(&driver_lock);
    atomic_store(&pending_stop, true);
    raise_irq();
    pthread_mutex_unlock(&driver_lock);
    pthread_join(cpu, NULL);
    atomic_store(&cpu_alive, false);
}
