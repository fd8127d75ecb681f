/* kilolib.h on the OpenSwarm kernel: written from the classic library's
 * documented behaviour. */
#include "kilolib.h"

#include <avr/eeprom.h>
#include <avr/io.h>
#include <util/crc16.h>

#include "openswarm/kernel.h"
#include "openswarm/kilobot.h"

#ifndef KILOLIB_LOOP_STACK
#define KILOLIB_LOOP_STACK 192 /* bytes for setup() and loop(), beyond the port's frame */
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
    kilo_turn_left = kilobot_calib.turn_left; /* read by kilobot_devices_init */
    kilo_turn_right = kilobot_calib.turn_right;
    kilo_straight_left = kilobot_calib.straight_left;
    kilo_straight_right = kilobot_calib.straight_right;
    kilo_uid = eeprom_read_word((const uint16_t *)KILOBOT_EEPROM_UID);
    rand_seed(rand_hard());
}

static void program(void *arg) {
    (void)arg;
    user_setup();
    for (;;) user_loop();
}

/* The robot starts as if the overhead controller had just sent RUN. */
void kilo_start(void (*setup)(void), void (*loop)(void)) {
    user_setup = setup;
    user_loop = loop;
    kilo_ticks = 0;
    tick_fraction = 0;
    kilobot_tick_hook = count_kilo_ticks;
    Sys_Start_Process_Ex(program, 0, KILOLIB_LOOP_STACK, 0, 0);
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

/* A blocking conversion on one channel (AVcc reference, /64 clock). */
static int16_t adc_read(uint8_t mux) {
    if (ADCSRA & _BV(ADSC)) return -1;
    ADMUX = mux;
    ADCSRA = _BV(ADEN) | _BV(ADSC) | _BV(ADPS2) | _BV(ADPS1);
    while (ADCSRA & _BV(ADSC)) {
    }
    return (int16_t)ADC;
}

int16_t get_ambientlight(void) { return adc_read(_BV(REFS0) | 7); }
int16_t get_voltage(void) { return adc_read(_BV(REFS0) | 6); }
int16_t get_temperature(void) { return adc_read(_BV(REFS1) | _BV(REFS0) | 8); } /* 1.1 V ref */

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

uint16_t message_crc(const message_t *msg) {
    uint16_t crc = 0xFFFF;
    for (uint8_t i = 0; i < 10; i++) crc = _crc_ccitt_update(crc, msg->rawdata[i]);
    return crc;
}
