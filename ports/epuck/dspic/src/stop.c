/* The robot stops for good after a fault outside any thread: everything
 * masked, the motors' coils released (no current through a stalled
 * stepper), what was printed sent, all eight ring LEDs lit so the robot
 * shows it. Only a reset leaves. */
#include "dspic_port.h"
#include "board_pins.h"
#include "p30f6014a_registers.h"

void dspic_stop(void) {
    SR |= SR_IPL_MASK;
    T4CON = 0;
    T5CON = 0;
    LATD &= (uint16_t)~COIL_PINS;
    LATA |= RING_LED_PINS;
    while (!(U1STA & USTA_TRMT)) {
        /* the last character leaves */
    }
    for (;;) {
        /* stopped */
    }
}
