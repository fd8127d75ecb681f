/* The e-puck2's four RGB LEDs, driven by its ESP32: the STM32 sends it
 * their colours over SPI1 (SCK PB3, MISO PB4, MOSI PA7, chip select PA15)
 * in one 12-byte packet. */
#ifndef EPUCK2_ESP32_LINK_H
#define EPUCK2_ESP32_LINK_H

#include <stdbool.h>
#include <stdint.h>

#define EPUCK2_ESP32_PACKET_BYTES 12u

void epuck2_esp32_link_init(void);

/* The packet for EPUCK_RGB(r, g, b) on all four LEDs: for LED2, LED4,
 * LED6, LED8 in turn red, green, blue, each in percent (0..3 becomes 0, 33,
 * 66, 100). */
void epuck2_esp32_rgb_packet(uint8_t rgb, uint8_t packet[EPUCK2_ESP32_PACKET_BYTES]);

/* The packet sent; false if SPI1 did not take it in time. */
bool epuck2_esp32_set_rgb_leds(uint8_t rgb);

#endif
