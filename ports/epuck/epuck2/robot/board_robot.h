/* What the robot board's files share. */
#ifndef EPUCK2_ROBOT_BOARD_ROBOT_H
#define EPUCK2_ROBOT_BOARD_ROBOT_H

/* Interrupt priorities (openswarm/cortex_m4.h: 0x10 never masked by the
 * kernel and must not call it; 0x20-0xD0 may call the kernel). */
#define ROBOT_PRIORITY_STEPPERS 0x10u  /* TIM3, TIM4: steps on time, no kernel calls */
#define ROBOT_PRIORITY_PROXIMITY 0x40u /* TIM2 and ADC, one level: they share the round's state */
#define ROBOT_PRIORITY_CAMERA 0x60u    /* DMA2 stream 1 and DCMI, one level: they share the frame's state */
#define ROBOT_PRIORITY_SELECTOR 0x80u  /* TIM7 */
#define ROBOT_PRIORITY_ESP32 0xC0u     /* TIM6: the ESP32's pause ends */
#define ROBOT_PRIORITY_CONSOLE 0xC0u   /* USART3: masked by the kernel, so a masked writer owns the buffer */

/* The outputs' drivers started, quiet, their interrupts on (board_devices.c). */
void board_outputs_start(void);

#endif
