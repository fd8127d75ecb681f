/* kilolib.h on the OpenSwarm kernel: written from the classic library's
 * documented behaviour. */
#include "kilolib.h"

#include <avr/eeprom.h>
#include <avr/io.h>
#include <string.h>
#include <util/crc16.h>

#include "kilolib_internal.h"
#include "openswarm/kilobot.h"

/* The transmitter thread only sleeps and transmits: the program's
 * callbacks run on the system stack (see transmitter). */
#ifndef KILOLIB_TX_STACK
#define KILOLIB_TX_STACK 48
#endif

volatile uint32_t kilo_ticks;
volatile uint16_t kilo_tx_period = TICKS_PER_SEC / 2; /* about half a second */
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

/* kilo_ticks advance TICKS_PER_SEC times a second, from the 1 ms tick:
 * every millisecond adds TICKS_PER_SEC thousandths of a tick. */
static uint16_t tick_fraction;
static void count_kilo_ticks(void) {
    tick_fraction = (uint16_t)(tick_fraction + TICKS_PER_SEC);
    if (tick_fraction >= 1000u) {
        tick_fraction = (uint16_t)(tick_fraction - 1000u);
        kilo_ticks++;
    }
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

void kilolib_program(void *arg) {
    (void)arg;
    user_setup();
    for (;;) user_loop();
}

/* Messages from other robots reach kilo_message_rx; the overhead
 * controller's system messages (types from 0x80) are kilolib's own. */
static bool deliver_message(sys_pid pid, sys_event_id e, const sys_event_data *d) {
    (void)pid;
    (void)e;
    const kilobot_ir_rx *rx = d->value;
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

static uint16_t ms_of_ticks(uint16_t ticks) {
    return (uint16_t)(((uint32_t)ticks * 1000u + TICKS_PER_SEC - 1u) / TICKS_PER_SEC);
}

/* kilolib's own work runs as an event handler, on the system (main)
 * stack: the program's transmit callbacks, as the classic library's run
 * from its timer interrupt, so they may do anything (print, compute a CRC)
 * that the transmitter's small stack could not hold; and an activity's
 * thread, which must wait until the thread it replaces is reaped. */
static message_t *outgoing;

static bool run_call(sys_pid pid, sys_event_id event, const sys_event_data *call) {
    (void)pid;
    (void)event;
    switch (*(const uint8_t *)call->value) {
    case KILOLIB_TX_DUE: outgoing = kilo_message_tx(); break;
    case KILOLIB_TX_SENT: kilo_message_tx_success(); break;
    case KILOLIB_START_ACTIVITY: kilolib_activity_thread_start(); break;
    default: break;
    }
    return true;
}

bool kilolib_call(uint8_t what) { return Sys_Send_Event(KILOLIB_EVENT_CALL, &what, 1) == SYS_OK; }

/* Every kilo_tx_period (give or take a random 0-15 ms, so robots that
 * started together drift apart), kilo_message_tx's message (its crc set by
 * the program, as with the classic library) goes out while the program
 * runs; a busy channel is tried again after a random few milliseconds. */
static void transmitter(void *arg) {
    (void)arg;
    for (;;) {
        Sys_Sleep(ms_of_ticks(kilo_tx_period) + (rand_soft() & 15u));
        if (kilolib_activity() != RUN) continue;
        outgoing = 0;
        if (!kilolib_call(KILOLIB_TX_DUE) || outgoing == 0) continue;
        while (kilobot_ir_transmit(outgoing->rawdata) != SYS_OK) Sys_Sleep(1u + (rand_soft() & 7u));
        kilolib_call(KILOLIB_TX_SENT);
    }
}

/* The robot starts as if the overhead controller had just sent RUN. */
void kilo_start(void (*setup)(void), void (*loop)(void)) {
    user_setup = setup;
    user_loop = loop;
    kilo_ticks = 0;
    tick_fraction = 0;
    kilobot_tick_hook = count_kilo_ticks;
    Sys_Subscribe_to_Event(KILOBOT_EVENT_IR_RX, SYS_PID_SYSTEM, deliver_message, 0);
    Sys_Register_Event_Sized(KILOLIB_EVENT_CALL, 1);
    Sys_Subscribe_to_Event(KILOLIB_EVENT_CALL, SYS_PID_SYSTEM, run_call, 0);
    kilolib_activity_start(RUN, kilolib_program);
    Sys_Start_Process_Ex(transmitter, 0, KILOLIB_TX_STACK, 0, 0);
    Sys_Start_Kernel();
    Sys_Run_SystemThread();
}

void set_motors(uint8_t left, uint8_t right) {
    kilobot_motors m = {left, right};
    Sys_Send_Event(KILOBOT_EVENT_MOTORS, &m, sizeof m);
}

void spinup_motors(void) {
    set_motors(255, 255);
    delay(15);
}

void set_color(uint8_t rgb) { Sys_Send_Event(KILOBOT_EVENT_LED, &rgb, 1); }

int16_t get_ambientlight(void) { return kilobot_adc_read(KILOBOT_ADC_LIGHT); }
int16_t get_voltage(void) { return kilobot_adc_read(KILOBOT_ADC_VOLTAGE); }
int16_t get_temperature(void) { return kilobot_adc_read(KILOBOT_ADC_TEMPERATURE); }

void delay(uint16_t ms) { Sys_Sleep(ms); }

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
