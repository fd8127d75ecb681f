/* What the LED shows while the program is not running, as with the classic
 * library: WAKEUP (and after RESET or SAVE) a short green flash every
 * 200 ms, ready for RUN; CHARGE a short red flash while the charger
 * charges, dark otherwise; VOLTAGE the battery level, steadily. */
#include "kilolib_internal.h"
#include "openswarm/kilobot.h"

#define FLASH_MS 1
#define PERIOD_MS 200

/* The battery level (kilobot_battery_light: the classic library's
 * thresholds). */
static uint8_t battery_colour(void) {
    int16_t v;
    while ((v = get_voltage()) < 0) delay(1); /* busy: a frame was being received */
    return kilobot_battery_light(v);
}

void kilolib_status_lights(void) {
    const uint8_t shown = kilolib_activity();
    for (;;) {
        uint8_t colour = shown == VOLTAGE  ? battery_colour()
                         : shown == CHARGE ? (kilobot_charging() ? RGB(1, 0, 0) : 0)
                                           : RGB(0, 3, 0);
        set_color(colour);
        delay(FLASH_MS);
        if (shown != VOLTAGE) set_color(0);
        delay(PERIOD_MS);
    }
}
