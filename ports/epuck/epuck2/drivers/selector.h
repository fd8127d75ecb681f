/* The e-puck2's 16-position selector: four input pins read 20 times a
 * second on TIM7's update. */
#ifndef EPUCK2_SELECTOR_H
#define EPUCK2_SELECTOR_H

#include <stdint.h>

/* Called from TIM7's interrupt with the position, 0..15, at every read. */
typedef void (*epuck2_selector_read)(uint8_t position);

void epuck2_selector_init(epuck2_selector_read on_read);
uint8_t epuck2_selector_position(void);

void TIM7_IRQHandler(void);

#endif
