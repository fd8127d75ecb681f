/*
 * The classic Kilobot library's API on the OpenSwarm kernel. Programs
 * written for it build unmodified:
 *
 *     #include <kilolib.h>
 *     void setup() { ... }
 *     void loop() { ... }
 *     int main() { kilo_init(); kilo_start(setup, loop); return 0; }
 *
 * Under OpenSwarm, setup() and loop() run on the system thread (main's
 * stack, as with the classic library: no thread stack); the message
 * callbacks run as event handlers, which interrupt loop() even while it
 * spins; delay() sleeps and serves them. The program may add threads and
 * events of its own with the kernel's Sys_* calls (its threads run while
 * it waits in delay() or between two loop() calls).
 */
#ifndef KILOLIB_H
#define KILOLIB_H

#include <stdint.h>

#include "message.h"

#ifdef __cplusplus
extern "C" {
#endif

#define RGB(r, g, b) ((uint8_t)(((r)&3) | (((g)&3) << 2) | (((b)&3) << 4)))
#define TICKS_PER_SEC 31

typedef struct {
    int16_t low_gain;
    int16_t high_gain;
} distance_measurement_t;

typedef void (*message_rx_t)(message_t *, distance_measurement_t *);
/* Most programs' message_rx ignores one of its two parameters (the
 * classic idiom: the distance, or the message itself): -Wextra's
 * unused-parameter would flag every classic program. Not pushed and popped
 * on purpose: it holds for the rest of the file that includes kilolib.h. */
#if defined(__GNUC__)
#pragma GCC diagnostic ignored "-Wunused-parameter"
#endif
typedef message_t *(*message_tx_t)(void);
typedef void (*message_tx_success_t)(void);

/* Clock ticks since kilo_start: one every 32.768 ms, as with the classic
 * library (30.52 a second; TICKS_PER_SEC is its rounded figure). */
extern volatile uint32_t kilo_ticks;
/* Time between two transmissions of kilo_message_tx's message, in the
 * classic library's Timer0 steps of 128 us, 255 to a tick: a message goes
 * out at the first tick after more steps than this since the last one.
 * Default 3906: every 16 ticks (0.524 s). */
extern volatile uint16_t kilo_tx_period;
extern uint16_t kilo_uid;
/* Motor duties that make this robot turn or go straight (from its EEPROM). */
extern uint8_t kilo_turn_left, kilo_turn_right, kilo_straight_left, kilo_straight_right;

extern message_rx_t kilo_message_rx;
extern message_tx_t kilo_message_tx;
extern message_tx_success_t kilo_message_tx_success;

void kilo_init(void);
void kilo_start(void (*setup)(void), void (*loop)(void));

void set_motors(uint8_t left, uint8_t right);
/* Both motors at full power for 15 ms: vibration motors need it to start. */
void spinup_motors(void);
void set_color(uint8_t rgb);

/* ADC readings, -1 if the converter is busy. */
int16_t get_ambientlight(void);
int16_t get_voltage(void);
int16_t get_temperature(void);

/* Distance in mm to the robot a message came from (EEPROM calibration). */
uint8_t estimate_distance(const distance_measurement_t *d);

void delay(uint16_t ms);
uint8_t rand_hard(void);
uint8_t rand_soft(void);
void rand_seed(uint8_t seed);
uint16_t message_crc(const message_t *msg);

#ifdef __cplusplus
}
#endif

#endif
