/* The e-puck2's LEDs the STM32 drives itself: the four red ring LEDs
 * (LED1, LED3, LED5, LED7 on PD5, PD6, PD10, PD11, lit by a low pin), the
 * body LED (PB2) and the front LED (PD14), lit by a high pin. The ring's
 * other four (LED2, 4, 6, 8) are the RGB LEDs the ESP32 drives
 * (esp32_link.h). Facts: GCtronic's firmware, board.h and src/leds.c. */
#ifndef EPUCK2_LEDS_H
#define EPUCK2_LEDS_H

#include <stdbool.h>
#include <stdint.h>

/* Pins as outputs, every LED off. */
void epuck2_leds_init(void);

/* Bit i of the mask is ring LED i (0 = LED1, the front one, clockwise
 * seen from above); the red ones are the even bits. */
void epuck2_leds_set_ring(uint8_t mask);
void epuck2_leds_set_body(bool on);
void epuck2_leds_set_front(bool on);

#endif
