/* The e-puck2's eight IR proximity sensors (TCRT1000): sampled in pairs
 * by ADC2, their emitters pulsed by pair, on TIM2's schedule; a whole
 * round (ambient and pulsed, all eight) 100 times a second. */
#ifndef EPUCK2_PROXIMITY_H
#define EPUCK2_PROXIMITY_H

#include "openswarm/epuck.h"

/* Called from the ADC's interrupt with each whole round. */
typedef void (*epuck2_proximity_round)(const epuck_proximity_samples *samples);

void epuck2_proximity_init(epuck2_proximity_round on_round);

void TIM2_IRQHandler(void);
void ADC_IRQHandler(void);

#endif
