/* The battery on the LED, for the overhead controller's VOLTAGE and
 * CHARGE (kilolib's status lights and the port's overhead control). */
#include <avr/io.h>

#include "openswarm/kilobot.h"

/* The classic library's thresholds, in ADC6 counts. */
uint8_t kilobot_battery_light(int16_t reading) {
    if (reading > 682) return KILOBOT_RGB(0, 3, 0);
    if (reading > 648) return KILOBOT_RGB(0, 0, 3);
    if (reading > 614) return KILOBOT_RGB(3, 3, 0);
    return KILOBOT_RGB(3, 0, 0);
}

/* The charger pulls PD0 low while it charges the battery. */
bool kilobot_charging(void) { return !(PIND & _BV(PD0)); }
