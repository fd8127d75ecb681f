/* kilolib.h on the OpenSwarm kernel: written from the classic library's
 * documented behaviour. */
#include "kilolib.h"

#include <avr/eeprom.h>
#include <avr/io.h>
#include <string.h>
#include <util/atomic.h>
#include <util/crc16.h>
#include <util/delay.h>

#include "kilolib_internal.h"
#include "openswarm/kilobot.h"

/* KILOLIB_IDLE_LOOP 1 (openswarm.json: "kernel": {"kilolib_idle_loop":
 * true}): a call of loop() during which kilo_ticks did not advance is
 * followed by a wait until the next kilo tick or message, asleep, instead
 * of calling loop() again at once. Programs that look only at kilo_ticks,
 * messages and what they set behave as before and the robot sleeps (in
 * the simulator a swarm of them runs about five times faster); a loop()
 * that counts its own calls as a clock, or polls a sensor for a change
 * faster than a tick (32 ms), runs differently: hence off by default. */
#ifndef KILOLIB_IDLE_LOOP
#define KILOLIB_IDLE_LOOP 0
#endif

volatile uint32_t kilo_ticks;
volatile uint16_t kilo_tx_period = 3906; /* 128 us steps: about half a second */
uint16_t kilo_uid;
uint8_t kilo_turn_left, kilo_turn_right, kilo_straight_left, kilo_straight_right;

static void no_rx(message_t *m, distance_measurement_t *d) {
    (void)m;
    (void)d;
}
static message_t *no_tx(void) { return 0; }
static void no_tx_success(void) {}

message_rx_t kilo_message_rx = no_rx;
message_tx_t kilo_message_tx = no_tx;
message_tx_success_t kilo_message_tx_success = no_tx_success;

static void (*user_setup)(void);
static void (*user_loop)(void);

/* kilo_ticks advance as the classic library's do, once per 256 steps of
 * its Timer0 (8 MHz / 1024): every 32.768 ms, 30.52 a second (its
 * TICKS_PER_SEC, 31, is rounded). From the milliseconds that pass,
 * exactly: 32.768 ms is 4096 / 125 ms, so every millisecond adds 125 /
 * 4096 of a tick. They come one at a time from the tick, and all at once
 * after the robot slept with the tick stopped (tickless idle), before the
 * program runs: it never sees kilo_ticks late, and the kilo tick needs no
 * wake-up of its own. */
#define TICK_FRACTION_PER_MS 125u
#define TICK_FRACTION_BITS 12u /* 4096 */
static uint16_t tick_fraction;
/* In parts of up to 255 ms, whose fractions fit 16 bits: an 8-bit
 * multiply, no 32-bit arithmetic but the count's own. */
static void count_kilo_ticks(uint16_t ms) {
    uint16_t fraction = tick_fraction;
    do {
        uint8_t part = ms > 255u ? 255u : (uint8_t)ms;
        ms = (uint16_t)(ms - part);
        fraction = (uint16_t)(fraction + part * TICK_FRACTION_PER_MS);
        uint8_t whole = (uint8_t)(fraction >> TICK_FRACTION_BITS);
        if (whole != 0) {
            kilo_ticks += whole;
            fraction &= (1u << TICK_FRACTION_BITS) - 1u;
        }
    } while (ms != 0);
    tick_fraction = fraction;
}

/* Milliseconds (1 to 33) until kilo_ticks next advances: the fraction
 * missing divided by 125, rounded up. The transmitter asks at every kilo
 * tick, so the division is a multiply: x / 125 is x * 33555 / 2^22 to
 * within 0.0006 for x up to 4220, which never carries the quotient past
 * the next whole number (a remainder is at most 124/125 = 0.992). */
static uint8_t ms_to_next_kilo_tick(void) {
    uint16_t fraction;
    ATOMIC_BLOCK(ATOMIC_RESTORESTATE) { fraction = tick_fraction; }
    uint16_t missing = (uint16_t)((1u << TICK_FRACTION_BITS) - fraction);
    return (uint8_t)(((uint32_t)(missing + TICK_FRACTION_PER_MS - 1u) * 33555u) >> 22);
}

static uint32_t kilo_ticks_now(void) {
    uint32_t t;
    ATOMIC_BLOCK(ATOMIC_RESTORESTATE) { t = kilo_ticks; }
    return t;
}

void kilo_init(void) {
    Sys_Init_Kernel();
    kilobot_devices_init();
    uint8_t osccal = eeprom_read_byte((const uint8_t *)KILOBOT_EEPROM_OSCCAL);
    if (osccal != 0xFF) OSCCAL = osccal; /* an erased EEPROM keeps the factory value */
    kilolib_identity_load();
    /* The uid keeps robots apart even where sensor noise is alike (a simulator). */
    rand_seed((uint8_t)(rand_hard() ^ kilo_uid ^ (kilo_uid >> 8)));
}

void kilolib_identity_load(void) {
    kilobot_calibration_load();
    kilo_turn_left = kilobot_calib.turn_left;
    kilo_turn_right = kilobot_calib.turn_right;
    kilo_straight_left = kilobot_calib.straight_left;
    kilo_straight_right = kilobot_calib.straight_right;
    kilo_uid = eeprom_read_word((const uint16_t *)KILOBOT_EEPROM_UID);
}

/* setup() runs once per power-up or reset, as with the classic library:
 * RUN after a pause resumes with loop(). A setup() cut short (another
 * activity replaced it) has not run. */
static bool setup_done;

/* Frames delivered so far (mod 256): the idle loop's wait ends at one. */
static volatile uint8_t frames_heard;

/* Until the next kilo tick or message (KILOLIB_IDLE_LOOP), asleep. */
static void wait_for_tick_or_message(uint32_t ticks) {
    uint8_t heard = frames_heard;
    while (kilo_ticks_now() == ticks && frames_heard == heard) {
        kilolib_stop_point();
        kilolib_wait(ms_to_next_kilo_tick());
    }
}

void kilolib_program(void) {
    if (!setup_done) {
        user_setup();
        setup_done = true;
    }
    for (;;) {
        kilolib_stop_point(); /* as the classic library's main loop looks between two loop() */
        uint32_t ticks = kilo_ticks_now();
        user_loop();
        if (KILOLIB_IDLE_LOOP && kilo_ticks_now() == ticks) wait_for_tick_or_message(ticks);
    }
}

/* Messages from other robots reach kilo_message_rx; the overhead
 * controller's system messages (types from 0x80) are kilolib's own. */
static bool kilolib_deliver_message(sys_pid pid, sys_event_id e, const sys_event_data *d) {
    (void)pid;
    (void)e;
    const kilobot_ir_rx *rx = d->value;
    frames_heard++;
    message_t msg;
    memcpy(msg.rawdata, rx->frame, sizeof msg.rawdata);
    if (msg.type >= SPECIAL) {
        kilolib_system_message(&msg);
        return true;
    }
    distance_measurement_t dist = {rx->low_gain, rx->high_gain};
    kilo_message_rx(&msg, &dist);
    return true;
}

/* kilolib's own work runs as an event handler, on the system (main)
 * stack: the program's transmit callbacks, as the classic library's run
 * from its timer interrupt, so they may do anything (print, compute a CRC). */
static void transmitter_looks(void);

static bool kilolib_run_call(sys_pid pid, sys_event_id event, const sys_event_data *call) {
    (void)pid;
    (void)event;
    if (*(const uint8_t *)call->value == KILOLIB_TX_DUE) transmitter_looks();
    return true;
}

bool kilolib_call(uint8_t what) { return Sys_Send_Event(KILOLIB_EVENT_CALL, &what, 1) == SYS_OK; }

/* kilo_tx_period counts the classic library's Timer0 steps (128 us), of
 * which each kilo tick adds 255 (saturating: no period is ever too long).
 * At each kilo tick once more steps than kilo_tx_period have passed since
 * the last message went out, kilo_message_tx's message (its crc set by the
 * program, as with the classic library) is sent while the program runs:
 * with the default 3906, every 16 ticks (0.524 s). The transmitter looks a
 * random 0-15 ms into each tick, so robots started together drift apart;
 * a busy channel is tried again after a random few milliseconds. */
#define STEPS_PER_KILO_TICK 255u

/* Without a division: asked at every kilo tick. 256 ticks are more than
 * any period. */
static uint16_t steps_after(uint16_t steps, uint32_t ticks) {
    if (ticks > 256u) return 0xFFFFu;
    uint32_t total = steps + (uint16_t)ticks * STEPS_PER_KILO_TICK;
    return total > 0xFFFFu ? 0xFFFFu : (uint16_t)total;
}

/* The transmitter, a handler the tick calls on (count_time): it looks a
 * random 0-15 ms into each kilo tick; a message the busy channel held back
 * is tried again after a random 1-8 ms. Its state, the handler's alone: */
static uint16_t tx_steps;   /* steps since the last message went out */
static uint32_t tx_seen;    /* kilo_ticks when it last looked */
static message_t *tx_held;  /* kilo_message_tx's message, not out yet */
static volatile uint8_t tx_wait_ms; /* until it looks again; 0: looking (its call queued) */

static void look_again(uint8_t ms) {
    ATOMIC_BLOCK(ATOMIC_RESTORESTATE) { tx_wait_ms = ms; }
}

/* A program that set no kilo_message_tx sends nothing: the default is not
 * called at every tick. Ticks that pass during a send count at once. */
static void transmitter_looks(void) {
    for (;;) {
        if (tx_held != 0) {
            if (kilobot_ir_transmit(tx_held->rawdata) != SYS_OK) {
                look_again((uint8_t)(1u + (rand_soft() & 7u)));
                return;
            }
            tx_held = 0;
            kilo_message_tx_success();
            tx_steps = 0;
        }
        uint32_t now = kilo_ticks_now();
        if (now == tx_seen) {
            look_again((uint8_t)(ms_to_next_kilo_tick() + (rand_soft() & 15u)));
            return;
        }
        tx_steps = steps_after(tx_steps, now - tx_seen);
        tx_seen = now;
        if (tx_steps > kilo_tx_period && kilolib_activity() == RUN && kilo_message_tx != no_tx)
            tx_held = kilo_message_tx();
    }
}

/* The port's clock hook, in the tick's interrupt (or all at once after a
 * sleep with the tick stopped): kilo_ticks, and the transmitter's call
 * when its wait is over. A full event queue (counted in event_queue_full)
 * has it asked again a millisecond later. */
static void count_time(uint16_t ms) {
    count_kilo_ticks(ms);
    uint8_t wait = tx_wait_ms;
    if (wait == 0) return;
    if (ms < wait) {
        tx_wait_ms = (uint8_t)(wait - ms);
        return;
    }
    tx_wait_ms = kilolib_call(KILOLIB_TX_DUE) ? 0 : 1;
}

/* The program waits, at most ms: asleep until the transmitter's next look
 * at the latest, which the kernel's deadlines do not know (tickless idle);
 * with the periodic tick every millisecond wakes it anyway. */
void kilolib_wait(uint32_t ms) {
    uint8_t tx = tx_wait_ms;
    Sys_Idle(tx != 0 && tx < ms ? tx : ms);
}

/* After power-up the robot starts as if the overhead controller had just
 * sent RUN; after RESET it waits for RUN, as the classic library does. */
void kilo_start(void (*setup)(void), void (*loop)(void)) {
    user_setup = setup;
    user_loop = loop;
    kilo_ticks = 0;
    tick_fraction = 0;
    kilobot_elapsed_hook = count_time;
    Sys_Subscribe_to_Event(KILOBOT_EVENT_IR_RX, SYS_PID_SYSTEM, kilolib_deliver_message, 0);
    Sys_Register_Event_Sized(KILOLIB_EVENT_CALL, 1);
    Sys_Subscribe_to_Event(KILOLIB_EVENT_CALL, SYS_PID_SYSTEM, kilolib_run_call, 0);
    if (kilolib_restarted())
        kilolib_activity_start(WAKEUP, kilolib_status_lights);
    else
        kilolib_activity_start(RUN, kilolib_program);
    transmitter_looks(); /* its first look: the first kilo tick */
    Sys_Start_Kernel();
    Sys_Run_SystemProgram(kilolib_run_activities);
}

void set_motors(uint8_t left, uint8_t right) {
    kilolib_stop_point();
    kilobot_motors m = {left, right};
    Sys_Send_Event(KILOBOT_EVENT_MOTORS, &m, sizeof m);
}

void spinup_motors(void) {
    set_motors(255, 255);
    delay(15);
}

void set_color(uint8_t rgb) {
    kilolib_stop_point();
    Sys_Send_Event(KILOBOT_EVENT_LED, &rgb, 1);
}

int16_t get_ambientlight(void) { return kilobot_adc_read(KILOBOT_ADC_LIGHT); }
int16_t get_voltage(void) { return kilobot_adc_read(KILOBOT_ADC_VOLTAGE); }
int16_t get_temperature(void) { return kilobot_adc_read(KILOBOT_ADC_TEMPERATURE); }

/* The classic library's delay busy-waits, and programs call it from their
 * message callbacks too: here those run as event handlers, which must not
 * wait for handlers (they run one at a time), so there it busy-waits as
 * the classic one does (interrupts run meanwhile; the handler overrun
 * report comes after 1 s). In setup() and loop() the robot sleeps, and
 * messages, the transmitter and the overhead controller are served
 * meanwhile; a thread of the app's sleeps. */
void delay(uint16_t ms) {
    if (Sys_In_SystemProgram()) {
        uint32_t end = Sys_Get_SystemTime() + ms;
        for (;;) {
            kilolib_stop_point();
            int32_t left = (int32_t)(end - Sys_Get_SystemTime());
            if (left <= 0) return;
            kilolib_wait((uint32_t)left);
        }
    }
    if (Sys_Sleep(ms) != SYS_E_CONTEXT) return;
    while (ms-- != 0) _delay_ms(1);
}

/* Noise from the temperature sensor's least significant bits. */
uint8_t rand_hard(void) {
    uint8_t r = 0;
    for (uint8_t bit = 0; bit < 8; bit++) {
        int16_t a = get_temperature(), b = get_temperature();
        r = (uint8_t)((r << 1) | ((a ^ b ^ (int16_t)TCNT0) & 1));
    }
    return r;
}

/* An 8-bit xorshift generator: fast, never stuck at zero. */
static uint8_t soft_state = 0xA5;
uint8_t rand_soft(void) {
    uint8_t x = soft_state;
    x ^= (uint8_t)(x << 3);
    x ^= (uint8_t)(x >> 5);
    x ^= (uint8_t)(x << 4);
    soft_state = x;
    return x;
}
void rand_seed(uint8_t seed) { soft_state = seed != 0 ? seed : 0xA5; }

uint16_t message_crc(const message_t *msg) { return kilobot_crc(msg->rawdata, 10); }

/* The port's distance pre-processor does it (ports/kilobot/src/devices/ir_distance.c). */
uint8_t estimate_distance(const distance_measurement_t *d) {
    return kilobot_ir_distance_mm(d->low_gain, d->high_gain);
}
