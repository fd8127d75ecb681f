/* The e-puck2's four RGB LEDs, driven by its ESP32: the STM32 sends it
 * their colours over SPI1 (SCK PB3, MISO PB4, MOSI PA7, chip select PA15)
 * in one 12-byte packet, at most one exchange per pause. */
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

/* The ESP32 needs a pause after each exchange (GCtronic's firmware waits
 * 350-500 us, src/spi_comm.c): here 500 us timed by TIM6 in one-pulse
 * mode at 1 MHz. */
#define EPUCK2_ESP32_PAUSE_US 500u

/* Sends the packet now, or, during the pause after the last exchange,
 * keeps the colour and sends it when the pause ends: a later colour
 * replaces a kept one (the latest wins). False if SPI1 did not take a
 * packet sent now in time. */
bool epuck2_esp32_set_rgb_leds(uint8_t rgb);

/* Exchanges SPI1 did not finish in time (now or at a pause's end). */
uint32_t epuck2_esp32_failed_exchanges(void);

/* The pause's end: TIM6's update. */
void TIM6_DAC_IRQHandler(void);

#endif
