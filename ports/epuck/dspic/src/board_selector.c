/* The e-puck's 16-position selector: four input pins, read every 10 ticks
 * (100 times a second, as the proximity rounds); the device layer makes an
 * event of a change only. */
#include "board.h"

#include "board_pins.h"
#include "../../src/epuck_board.h"
#include "p30f6014a_registers.h"

#define TICKS_PER_READ 10u

/* From the tick interrupt, inside the kernel's bracket. */
void board_selector_poll(void) {
    static uint8_t ticks;
    if (++ticks < TICKS_PER_READ) return;
    ticks = 0;
    epuck_selector_arrived((uint8_t)((PORTG >> SELECTOR_SHIFT) & SELECTOR_MASK));
}
