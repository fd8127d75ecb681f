/* Tickless idle (OS_CFG_TICKLESS): while every thread waits, SysTick
 * stretches one of its periods over the ticks until the kernel's next
 * deadline (or the board's next tick hook), and the CPU sleeps through
 * them in one WFI instead of waking every millisecond.
 *
 * SysTick never stops, so its phase never drifts: only its reload value
 * changes, and a new reload value takes effect at the next wrap. The
 * idle thread sets the stretched reload (k ticks' worth of counts); the
 * next tick comes as usual, reloads the counter with the stretched period
 * and puts the ordinary reload back for the wrap after; the stretched
 * period then ends exactly on the tick k ticks later, where the k - 1
 * ticks in between are credited (os_ticks_slept) and the tick itself is
 * an ordinary one. A sleep of D ticks costs two interrupts instead of D.
 *
 * An interrupt that calls the kernel meanwhile (port_tickless_wake, from
 * os_isr_enter) credits the ticks the counter says have passed and puts
 * the counter back on the tick grid: the counts to the next tick are
 * loaded by a write of the current value, then the ordinary reload. The
 * kernel's time is exact; only the grid may move by the few counts between
 * the read and the write (under QEMU less than 0.4 us a re-phase:
 * qemu.tickless_time's grid line). */
#include "openswarm/cortex_m4.h"
#include "openswarm/port.h"
#include "openswarm/system_time.h"
#include "system_control.h"

#if OS_CFG_TICKLESS

#define SYSTICK_MAX_COUNTS 0x1000000u /* a 24-bit counter */
/* A tick due within this many counts is waited for rather than put back
 * on the grid: the write that does it must come before the tick. */
#define REPHASE_MARGIN 256u

/* AWAKE: every tick interrupts. ARMED: the stretched reload is set, the
 * next tick will load it. STRETCHED: the counter runs the stretched
 * period, which began at a tick already counted. */
enum { AWAKE, ARMED, STRETCHED };
static volatile uint8_t state;
static uint32_t stretch_ticks; /* k: the stretched period's length in ticks */

static uint32_t tick_counts(void) { return board_core_hz / 1000u; }

static uint32_t exception_number(void) {
    uint32_t ipsr;
    __asm__ __volatile__("mrs %0, ipsr" : "=r"(ipsr));
    return ipsr & 0x1FFu;
}

/* The SysTick exception is pending or being handled: the counter wrapped
 * since its handler last looked. */
static bool systick_wrapped(void) {
    return (SCB_ICSR & SCB_ICSR_PENDSTSET) != 0 || (SCB_SHCSR & SCB_SHCSR_SYSTICKACT) != 0;
}

/* The counter restarts so that it wraps `counts` counts after it was read,
 * on the tick grid, and reloads ordinary periods from there. The counter
 * takes the written reload at the clock after the write of CVR. */
static void rephase(uint32_t counts) {
    SYST_RVR = counts - 1u;
    SYST_CVR = 0;
    while (SYST_CVR == 0) {
    }
    SYST_RVR = tick_counts() - 1u;
}

static void credit(uint32_t ticks) {
    state = AWAKE;
    if (ticks != 0) os_ticks_slept((uint16_t)ticks);
}

/* An interrupt other than the tick came while the counter runs the
 * stretched period: the ticks it holds that have passed are credited and
 * the counter is put back on the grid. A tick due any moment is let pass
 * first. start_pending: the tick that loaded the period is still to be
 * handled (the period has just begun: its end is far). */
static void wake_in_stretch(bool start_pending) {
    uint32_t per_tick = tick_counts();
    uint32_t top = stretch_ticks * per_tick - 1u;
    for (;;) {
        uint32_t count = SYST_CVR;
        if (!start_pending && systick_wrapped()) { /* the period ended: its tick is the handler's */
            credit(stretch_ticks - 1u);
            return;
        }
        uint32_t gone = top - count;
        uint32_t passed = gone / per_tick;
        uint32_t to_next = (passed + 1u) * per_tick - gone;
        if (to_next >= REPHASE_MARGIN) {
            rephase(to_next);
            credit(passed);
            return;
        }
    }
}

/* First in os_isr_enter: cheap when awake. */
void port_tickless_wake(void) {
    if (state == AWAKE) return;
    bool in_tick = exception_number() == 15u;
    bool start_pending = false;
    if (state == ARMED) {
        SYST_RVR = tick_counts() - 1u; /* the wrap after this one is ordinary */
        if (in_tick) {                 /* this tick loaded the stretched period */
            state = STRETCHED;
            return;
        }
        if (SYST_CVR < tick_counts()) { /* no tick loaded it: nothing changed */
            state = AWAKE;
            return;
        }
        start_pending = true; /* a tick loaded it, and is still to be handled */
    }
    if (in_tick)
        credit(stretch_ticks - 1u);
    else
        wake_in_stretch(start_pending);
}

/* The ticks the CPU may sleep through: the kernel's, the board's hook's
 * and SysTick's 24 bits. */
static uint32_t ticks_to_sleep(uint32_t kernel_ticks) {
    uint32_t ticks = kernel_ticks;
    if (cortex_m4_tick_hook != NULL) {
        int32_t hook_ticks = (int32_t)(cortex_m4_tick_hook_ms - Sys_Get_SystemTime());
        uint32_t hook_wait = hook_ticks > 0 ? (uint32_t)hook_ticks : 0u; /* a time past: every tick */
        if (hook_wait < ticks) ticks = hook_wait;
    }
    uint32_t longest = SYSTICK_MAX_COUNTS / tick_counts() + 1u;
    return ticks < longest ? ticks : longest;
}

void port_idle_for(uint32_t ticks) {
    uint32_t sleep = ticks_to_sleep(ticks);
    if (sleep < 3u) { /* a stretch of one tick is no stretch */
        port_idle();
        return;
    }
    stretch_ticks = sleep - 1u;
    SYST_RVR = stretch_ticks * tick_counts() - 1u;
    state = ARMED;
    do port_idle(); /* the tick that loads the stretch comes back here */
    while (state != AWAKE);
}
#endif
