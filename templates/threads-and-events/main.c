/* {{name}}: the OpenSwarm paper's Listing 1 on a Kilobot.
 *  - a computing thread counts primes without ever yielding (it is
 *    preempted every 10 ms, so the rest still runs);
 *  - a reactive handler turns every "colour" reading of a virtual sensor
 *    into motor speeds, cooperatively, between threads;
 *  - a logging thread prints time, primes and speeds every 250 ms, waiting
 *    for 250 occurrences of the 1 ms timer event. */
#include <stdio.h>

#include "debug.h"
#include "openswarm/kernel.h"
#include "openswarm/kilobot.h"

#define EV_COLOUR SYS_EVENT_FIRST_FREE
enum { NOTHING, OBJECT, ROBOT };

static volatile uint32_t primes;
static volatile uint8_t left, right;

static void compute(void) {
    for (uint32_t n = 2;; n++) {
        uint32_t d = 2;
        while (d * d <= n && n % d != 0) d++;
        if (d * d > n) primes++;
    }
}

/* The virtual one-pixel sensor: a colour every 100 ms. */
static void sensor(void) {
    for (uint8_t i = 0;; i++) {
        Sys_Sleep(100);
        Sys_Send_IntEvent(EV_COLOUR, (int16_t)(i % 3));
    }
}

static bool steer(sys_pid pid, sys_event_id event, const sys_event_data *data) {
    (void)pid;
    (void)event;
    int16_t colour = *(const int16_t *)data->value;
    kilobot_motors m = {0, 0};
    if (colour == OBJECT) m.left = m.right = kilobot_calib.straight_left; /* push it */
    if (colour == ROBOT) m.left = kilobot_calib.turn_left;                /* avoid it */
    left = m.left;
    right = m.right;
    Sys_Send_Event(KILOBOT_EVENT_MOTORS, &m, sizeof m);
    return true;
}

static bool wait250(const sys_event_data *data) {
    static uint8_t count;
    (void)data;
    if (++count < 250) return false;
    count = 0;
    return true;
}

static void logger(void *arg) {
    (void)arg;
    for (;;) {
        Sys_Wait_for_Condition(SYS_EVENT_1MS_TIMER, wait250, NULL, 0, NULL);
        /* A consistent snapshot: no switch and no handler inside the section,
         * so the 4-byte count and the two speeds are read whole. */
        Sys_Start_CriticalSection();
        uint32_t n = primes;
        uint8_t l = left, r = right;
        Sys_End_CriticalSection();
        printf("%lu:(%u,%u) primes %lu\n", (unsigned long)Sys_Get_SystemTime(), l, r,
               (unsigned long)n);
    }
}

int main(void) {
    Sys_Init_Kernel();
    kilobot_devices_init();
    debug_init();
    Sys_Register_Event(EV_COLOUR);
    Sys_Subscribe_to_Event(EV_COLOUR, SYS_PID_SYSTEM, steer, NULL);
    Sys_Start_Process(compute);
    Sys_Start_Process(sensor);
    Sys_Start_Process_Ex(logger, NULL, 160, 0, NULL); /* printf needs room */
    Sys_Start_Kernel();
    Sys_Run_SystemThread();
    return 0;
}
