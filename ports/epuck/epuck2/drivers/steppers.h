/* The e-puck2's two stepper motors, driven coil by coil from GPIOE: the
 * right one's phases on every update of TIM3, the left one's of TIM4. */
#ifndef EPUCK2_STEPPERS_H
#define EPUCK2_STEPPERS_H

#include <stdint.h>

void epuck2_steppers_init(void);
/* Steps per second, + forward, each at most +-1000 (the device layer's
 * processor has limited them already). */
void epuck2_steppers_set(int16_t left, int16_t right);
/* Steps made since start, + forward. */
int32_t epuck2_steppers_position(int side); /* 0 left, 1 right */

void TIM3_IRQHandler(void);
void TIM4_IRQHandler(void);

#endif
