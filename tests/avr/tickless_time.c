/* Tickless idle keeps time exact (avr.tickless_time). Every thread sleeps
 * or waits most of the time, so the robot sleeps with the tick stopped:
 *   - a 10 s sleep ends at 10000 ms, and the LED it then lights shows
 *     simavr's own clock (the trace) agreeing: 10.000 s;
 *   - a 2.5 s timeout ends at 12500 ms (12.500 s on the trace);
 *   - an interrupt in the middle of both (Timer2's 40th, at 1280 ms; the
 *     39 before it do not call the kernel) reads the exact time, and wakes
 *     the thread waiting for what it sends, at once;
 *   - two threads that never block keep the tick: the time slice switches
 *     between them every 10 ms (about 20 switches in 200 ms). */
#include "busy_threads.h"
#include "openswarm/kernel.h"
#include "openswarm/kilobot.h"
#include "openswarm/kilobot_sim.h"
#include "openswarm/port.h"

#include <avr/interrupt.h>
#include <avr/io.h>

#define EV_POKE SYS_EVENT_FIRST_FREE
#define EV_NEVER (SYS_EVENT_FIRST_FREE + 1)

static void say(const char *flash_text, uint32_t value) {
    sim_puts_P(flash_text);
    sim_put_uint(value);
    sim_putc('\n');
}

/* Timer2 in CTC mode, 8 MHz / 1024 / 250: every 32 ms. */
static volatile uint8_t compares;
ISR(TIMER2_COMPA_vect) {
    if (++compares != 40) return;
    TIMSK2 = 0;
    os_isr_enter();
    uint32_t now = Sys_Get_SystemTime();
    Sys_Send_Event(EV_POKE, &now, sizeof now);
    os_isr_exit();
}

static void waiter(void *arg) {
    (void)arg;
    TCCR2A = _BV(WGM21);
    OCR2A = 249;
    TIMSK2 = _BV(OCIE2A);
    TCCR2B = _BV(CS22) | _BV(CS21) | _BV(CS20);
    uint32_t sent_at = 0;
    Sys_Wait_for_Event(EV_POKE, &sent_at, sizeof sent_at, NULL);
    uint32_t now = Sys_Get_SystemTime();
    kilobot_led_apply(KILOBOT_RGB(0, 0, 1));
    say(PSTR("the interrupt read ms "), sent_at);
    say(PSTR("its waiter woke at ms "), now);
}

static void sleeper(void *arg) {
    (void)arg;
    Sys_Sleep(10000);
    kilobot_led_apply(KILOBOT_RGB(1, 0, 0));
    say(PSTR("a 10 s sleep woke at ms "), Sys_Get_SystemTime());
    sys_status st = Sys_Wait_for_Event_Timeout(EV_NEVER, 2500, NULL, 0, NULL);
    kilobot_led_apply(KILOBOT_RGB(0, 1, 0));
    say(PSTR("a 2.5 s timeout ended at ms "), Sys_Get_SystemTime());
    say(PSTR("timed out "), (uint32_t)(st == SYS_E_TIMEOUT));
    busy_threads_result busy = busy_threads_run();
    say(PSTR("busy threads: a 200 ms sleep woke at ms "), busy.woke_at_ms);
    say(PSTR("switches meanwhile "), busy.switches);
    say(PSTR("both spun "), (uint32_t)busy.both_spun);
    sim_exit(0);
}

int main(void) {
    Sys_Init_Kernel();
    Sys_Register_Event_Sized(EV_POKE, sizeof(uint32_t));
    Sys_Register_Event_Sized(EV_NEVER, 0);
    Sys_Start_Process_Ex(waiter, NULL, 0, 0, NULL);
    Sys_Start_Process_Ex(sleeper, NULL, 0, 0, NULL);
    Sys_Start_Kernel();
    Sys_Run_SystemThread();
    return 0;
}
