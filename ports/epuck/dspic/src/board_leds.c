/* The e-puck's LEDs: eight around the ring, the front (red) and body
 * (green) ones, each a pin driven high to light. The dsPIC e-puck has no
 * RGB LEDs: the robot's status LED (ROBOT_EVENT_LED, EPUCK_EVENT_RGB_LEDS,
 * which blinky uses) lights the body LED whenever its colour is not black,
 * so an app driving epuck_body_led as well shares that LED. */
#include "board.h"

#include "board_pins.h"
#include "../../src/epuck_board.h"
#include "p30f6014a_registers.h"

void board_leds_init(void) {
    TRISA &= (uint16_t)~RING_LED_PINS;
    TRISC &= (uint16_t)~(FRONT_LED_PIN | BODY_LED_PIN);
}

void epuck_board_set_ring_leds(uint8_t mask) {
    static const uint16_t pins[8] = RING_LED_PINS_IN_ORDER;
    uint16_t lit = 0;
    for (unsigned i = 0; i < 8u; i++)
        if (mask & (1u << i)) lit |= pins[i];
    LATA = (uint16_t)((LATA & ~RING_LED_PINS) | lit);
}

static void set_latc(uint16_t pin, bool on) {
    if (on)
        LATC |= pin;
    else
        LATC &= (uint16_t)~pin;
}

void epuck_board_set_body_led(bool on) { set_latc(BODY_LED_PIN, on); }
void epuck_board_set_front_led(bool on) { set_latc(FRONT_LED_PIN, on); }
void epuck_board_set_rgb_leds(uint8_t rgb) { set_latc(BODY_LED_PIN, rgb != 0); }
