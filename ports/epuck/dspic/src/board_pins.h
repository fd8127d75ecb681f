/* Where the e-puck's devices meet the dsPIC30F6014A (the e-puck library's
 * e_epuck_ports.h, version 1.0 of November 2005, and the e-puck
 * schematics): the lower layer's files share these. */
#ifndef BOARD_PINS_H
#define BOARD_PINS_H

/* Ring LEDs 0..7, from the front clockwise, on PORTA. */
#define RING_LED_PINS_IN_ORDER {1u << 6, 1u << 7, 1u << 9, 1u << 12, 1u << 10, 1u << 13, 1u << 14, 1u << 15}
#define RING_LED_PINS 0xF6C0u
#define FRONT_LED_PIN (1u << 1) /* RC1, red */
#define BODY_LED_PIN (1u << 2)  /* RC2, green */

/* Stepper coils (phases A..D) on PORTD: motor 1, the left, RD0..RD3,
 * stepped by Timer5; motor 2, the right, RD4..RD7, by Timer4. */
#define LEFT_COILS_SHIFT 0u
#define RIGHT_COILS_SHIFT 4u
#define COIL_PINS 0x00FFu

/* IR emitters, each lighting two sensors (i and i + 4): pair 0 RF7,
 * pair 1 RF8 (PORTF); pair 2 RG0, pair 3 RG1 (PORTG). */
#define PULSE_PAIR0_PIN (1u << 7)
#define PULSE_PAIR1_PIN (1u << 8)
#define PULSE_PAIR2_PIN (1u << 0)
#define PULSE_PAIR3_PIN (1u << 1)
#define PULSE_PINS_F (PULSE_PAIR0_PIN | PULSE_PAIR1_PIN)
#define PULSE_PINS_G (PULSE_PAIR2_PIN | PULSE_PAIR3_PIN)
/* IR receiver i on analog input AN(8 + i) (RB8..RB15). */
#define PROXIMITY_FIRST_CHANNEL 8u
#define PROXIMITY_ANALOG_PINS 0xFF00u

/* The selector's 4 bits on RG6..RG9 (inputs, as after reset). */
#define SELECTOR_SHIFT 6u
#define SELECTOR_MASK 0xFu

/* The camera (PO3030K): pixel bytes on RD8..RD15 (bit 0 on RD8); HREF on
 * RC3 = T4CK and VSYNC on RC4 = T5CK, so Timer4 and Timer5 count them;
 * PCLK on RC14; its reset, active low, on RC13; I2C on RG2 (SCL), RG3
 * (SDA), the I2C module's own pins. */
#define CAMERA_DATA_PINS 0xFF00u
#define CAMERA_HREF_PIN (1u << 3)
#define CAMERA_VSYNC_PIN (1u << 4)
#define CAMERA_PCLK_PIN (1u << 14)
#define CAMERA_RESET_PIN (1u << 13)

#endif
