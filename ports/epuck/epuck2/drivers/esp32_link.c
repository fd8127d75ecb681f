/* The SPI link to the e-puck2's ESP32, as GCtronic's firmware runs it
 * (src/spi_comm.c, src/leds.c): SPI1 master at 10.5 MHz (APB2's 84 MHz /
 * 8, the firmware's divider, its note giving the ESP32's limit as 10 MHz),
 * mode 0, most significant bit first, chip select by software on PA15, 12 bytes an
 * exchange. The ESP32 answers at the same time (its first byte is the
 * button's state); the answer is read only to keep the receiver from
 * overrunning. Facts: ports/epuck/README.md. */
#include "esp32_link.h"

#include "stm32f4_registers.h"

#define LEDS 4u
#define PERCENT_MAX 100u
#define PIN_CS 15u  /* PA15 */
#define PIN_MOSI 7u /* PA7 */
#define PIN_SCK 3u  /* PB3 */
#define PIN_MISO 4u /* PB4 */
#define AF_SPI1 5u
/* A byte takes under 1 us at 10.5 MHz; this bounds a wait at about 1 ms. */
#define TIMEOUT_POLLS 20000u

void epuck2_esp32_link_init(void) {
    RCC_ENABLES->AHB1ENR |= RCC_AHB1ENR_GPIOAEN | RCC_AHB1ENR_GPIOBEN;
    RCC_ENABLES->APB2ENR |= RCC_APB2ENR_SPI1EN;
    GPIOA->BSRR = 1u << PIN_CS; /* deselected before it is an output */
    stm32_gpio_mode(GPIOA, PIN_CS, GPIO_MODE_OUTPUT);
    stm32_gpio_af(GPIOA, PIN_MOSI, AF_SPI1);
    stm32_gpio_af(GPIOB, PIN_SCK, AF_SPI1);
    stm32_gpio_af(GPIOB, PIN_MISO, AF_SPI1);
    /* Master, the chip select ours (SSM, with SSI high so the block never
     * sees itself deselected), CPOL = CPHA = 0, 8 bits, MSB first. */
    SPI1->CR1 = SPI_CR1_MSTR | SPI_CR1_BR_DIV8 | SPI_CR1_SSM | SPI_CR1_SSI;
    SPI1->CR1 |= SPI_CR1_SPE;
}

void epuck2_esp32_rgb_packet(uint8_t rgb, uint8_t packet[EPUCK2_ESP32_PACKET_BYTES]) {
    const uint8_t levels[3] = {(uint8_t)(rgb & 3u), (uint8_t)((rgb >> 2) & 3u), (uint8_t)((rgb >> 4) & 3u)};
    for (unsigned led = 0; led < LEDS; led++)
        for (unsigned c = 0; c < 3u; c++) packet[3u * led + c] = (uint8_t)(levels[c] * PERCENT_MAX / 3u);
}

static bool wait_for(uint32_t flag, bool set) {
    for (uint32_t n = 0; n < TIMEOUT_POLLS; n++) {
        STM32_POLL();
        if (((SPI1->SR & flag) != 0) == set) return true;
    }
    return false;
}

static bool exchange(const uint8_t *bytes, unsigned count) {
    bool ok = true;
    for (unsigned i = 0; ok && i < count; i++) {
        ok = wait_for(SPI_SR_TXE, true);
        if (ok) SPI1->DR = bytes[i];
        ok = ok && wait_for(SPI_SR_RXNE, true);
        if (ok) (void)SPI1->DR; /* the ESP32's byte: read, so no overrun */
    }
    return ok && wait_for(SPI_SR_BSY, false); /* the last bit out before CS rises */
}

bool epuck2_esp32_set_rgb_leds(uint8_t rgb) {
    uint8_t packet[EPUCK2_ESP32_PACKET_BYTES];
    epuck2_esp32_rgb_packet(rgb, packet);
    GPIOA->BSRR = 1u << (PIN_CS + 16u); /* select: low */
    bool ok = exchange(packet, EPUCK2_ESP32_PACKET_BYTES);
    GPIOA->BSRR = 1u << PIN_CS;
    return ok;
}
