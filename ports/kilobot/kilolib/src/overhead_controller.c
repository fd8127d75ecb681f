/* The overhead controller's system messages (types from 0x80), handled as
 * the classic Kilobot library documents them. Each asks the robot for one
 * activity, which replaces the one before. */
#include <avr/interrupt.h>
#include <avr/io.h>

#include "kilolib_internal.h"
#include "openswarm/kilobot.h"
#include "openswarm/kilobot_sim.h"

#ifndef KILOLIB_LOOP_STACK
#define KILOLIB_LOOP_STACK 192 /* bytes for setup() and loop(), beyond the port's frame */
#endif

/* The Kilobot's IR bootloader lives in the ATmega328P's 4 KB boot section,
 * from byte address 0x7000 to the end of the flash. */
#define BOOTLOADER_ADDRESS 0x7000

static uint8_t activity;
static sys_pid activity_pid = SYS_PID_NONE;

uint8_t kilolib_activity(void) { return activity; }

static sys_process_fn activity_fn; /* the thread the current activity runs, if any */

/* The current activity ends (its thread killed, motors off, LED dark) and
 * the new one's thread, if any, starts once the old thread is reaped:
 * every activity gets the program's stack size, so the old thread's slot
 * and stack are the ones it reuses (they are not free before). */
void kilolib_activity_start(uint8_t what, sys_process_fn fn) {
    if (activity_pid != SYS_PID_NONE) {
        Sys_Kill_Process(activity_pid); /* SYS_E_INVALID if it had ended: nothing to kill */
        activity_pid = SYS_PID_NONE;
        /* Sent as events, after whatever the killed thread still had queued. */
        set_motors(0, 0);
        set_color(0);
    }
    activity = what;
    activity_fn = fn;
    /* A full event queue (counted in event_queue_full): start it now, which
     * works unless the old thread still holds the only slot. */
    if (fn != 0 && !kilolib_call(KILOLIB_START_ACTIVITY)) kilolib_activity_thread_start();
}

void kilolib_activity_thread_start(void) {
    if (activity_fn != 0 && activity_pid == SYS_PID_NONE &&
        Sys_Start_Process_Ex(activity_fn, 0, KILOLIB_LOOP_STACK, 0, &activity_pid) == SYS_OK)
        sim_thread_name(activity_pid, PSTR("kilolib program (setup, loop)"));
}

/* The same request again (the overhead controller repeats its messages)
 * leaves the activity running undisturbed. */
static void activity_switch(uint8_t what, sys_process_fn fn) {
    if (activity != what) kilolib_activity_start(what, fn);
}

/* BOOT: the bootloader takes the robot over to receive a new program.
 * It sets up the timers and interrupts it uses itself, but an interrupt of
 * ours left enabled and pending (the IR input capture) would enter its
 * vector table, where no handler expects it: ours are masked and cleared. */
static void __attribute__((noreturn)) bootloader_jump(void) {
    cli();
    kilobot_motors_apply(0, 0);
    TIMSK0 = 0;
    TIMSK1 = 0;
    TIFR0 = _BV(OCF0B) | _BV(OCF0A) | _BV(TOV0); /* flags clear when written 1 */
    TIFR1 = _BV(ICF1) | _BV(OCF1B) | _BV(OCF1A) | _BV(TOV1);
    __asm__ __volatile__("jmp %0" ::"i"(BOOTLOADER_ADDRESS)); /* a byte address, to the assembler */
    __builtin_unreachable();
}

/* RESET: the program starts over from scratch, as the classic library's
 * jump to address 0 does: the C runtime sets the stack and every static
 * afresh (the kernel's state, kilo_ticks, the program's own), main() runs
 * kilo_init and kilo_start, and the robot waits for RUN, which runs setup().
 * A jump leaves the peripherals as they were, so first each one the port
 * or a program may use goes back to its power-up state (datasheet reset
 * values: stopped, interrupts masked, flags cleared, pins inputs): the
 * kernel and the devices then start as after a reset, and no interrupt
 * of the old run fires before its driver is ready for it. */
#define RESTART_MARK 0x5A3Cu
static uint16_t restart_mark __attribute__((section(".noinit"))); /* kept by the jump */

bool kilolib_restarted(void) {
    bool restarted = restart_mark == RESTART_MARK;
    restart_mark = 0;
    return restarted;
}

static void peripherals_as_at_power_up(void) {
    TIMSK0 = TIMSK1 = TIMSK2 = 0;
    TCCR0A = TCCR0B = TCCR1A = TCCR1B = TCCR1C = TCCR2A = TCCR2B = ASSR = 0;
    TCNT0 = OCR0A = OCR0B = TCNT2 = OCR2A = OCR2B = 0;
    TCNT1 = OCR1A = OCR1B = ICR1 = 0;
    TIFR0 = TIFR1 = TIFR2 = 0xFF; /* flags clear when written 1 */
    ADCSRA = _BV(ADIF);           /* off, its flag cleared */
    ADCSRB = ADMUX = DIDR0 = DIDR1 = 0;
    ACSR = _BV(ACI);
    /* The serial port's interrupts only: debug_init sets the rest again, and
     * a transmitter disabled mid-byte never shows an empty buffer again in
     * simavr 1.6 (printf would wait for ever). */
    UCSR0B &= (uint8_t) ~(_BV(RXCIE0) | _BV(TXCIE0) | _BV(UDRIE0));
    SPCR = TWCR = 0;
    EIMSK = EICRA = PCICR = PCMSK0 = PCMSK1 = PCMSK2 = 0;
    EIFR = PCIFR = 0xFF;
    SMCR = PRR = 0;
    DDRB = DDRC = DDRD = PORTB = PORTC = PORTD = 0;
}

static void __attribute__((noreturn)) restart(void) {
    cli();
    peripherals_as_at_power_up();
    restart_mark = RESTART_MARK;
    __asm__ __volatile__("jmp 0");
    __builtin_unreachable();
}

void kilolib_system_message(const message_t *msg) {
    switch (msg->type) {
    case BOOT:
        bootloader_jump();
    case RESET:
        restart();
    case SLEEP:
        activity_switch(SLEEP, 0);
        break;
    case WAKEUP:
    case CHARGE:
    case VOLTAGE:
        activity_switch(msg->type, kilolib_status_lights);
        break;
    case RUN:
        activity_switch(RUN, kilolib_program);
        break;
    case CALIB:
    case READUID:
        kilolib_calibration_message(msg);
        break;
    default:
        break; /* BOOTPGM_PAGE, BOOTPGM_SIZE: for the bootloader */
    }
}
