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
/* TIM6 counts at APB1's timer clock (84 MHz) / 84 = 1 MHz. */
#define PAUSE_PRESCALER (EPUCK2_APB1_TIMER_HZ / 1000000u - 1u)
#define TIM_CR1_URS (1u << 2) /* only an overflow raises UIF, not UG */

/* The pause's state, shared with TIM6's interrupt: the thread side
 * touches it only with the interrupt held off (TIM6's UIE clear). */
static bool pausing;
static bool colour_kept;
static uint8_t kept_colour;
static uint32_t failed_exchanges;

static void pause_timer_init(void) {
    RCC_ENABLES->APB1ENR |= RCC_APB1ENR_TIM6EN;
    TIM6->CR1 = TIM_CR1_URS;
    TIM6->PSC = PAUSE_PRESCALER;
    TIM6->ARR = EPUCK2_ESP32_PAUSE_US - 1u;
    TIM6->EGR = TIM_EGR_UG; /* loads the prescaler */
    TIM6->SR = 0;
    TIM6->DIER = TIM_DIER_UIE;
}

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
    pausing = colour_kept = false;
    failed_exchanges = 0;
    pause_timer_init();
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

/* One exchange, then the pause before the next. */
static bool send_and_pause(uint8_t rgb) {
    uint8_t packet[EPUCK2_ESP32_PACKET_BYTES];
    epuck2_esp32_rgb_packet(rgb, packet);
    GPIOA->BSRR = 1u << (PIN_CS + 16u); /* select: low */
    bool ok = exchange(packet, EPUCK2_ESP32_PACKET_BYTES);
    GPIOA->BSRR = 1u << PIN_CS;
    if (!ok) failed_exchanges++;
    pausing = true;
    TIM6->SR = ~TIM_SR_UIF;
    TIM6->CNT = 0;
    TIM6->CR1 = TIM_CR1_URS | TIM_CR1_OPM | TIM_CR1_CEN;
    return ok;
}

bool epuck2_esp32_set_rgb_leds(uint8_t rgb) {
    TIM6->DIER = 0;
    bool ok = true;
    if (pausing) {
        kept_colour = rgb;
        colour_kept = true;
    } else {
        ok = send_and_pause(rgb);
    }
    TIM6->DIER = TIM_DIER_UIE; /* an end that came meanwhile is taken now */
    return ok;
}

uint32_t epuck2_esp32_failed_exchanges(void) { return failed_exchanges; }

void TIM6_DAC_IRQHandler(void) {
    if ((TIM6->DIER & TIM_DIER_UIE) == 0 || (TIM6->SR & TIM_SR_UIF) == 0) return;
    TIM6->SR = ~TIM_SR_UIF;
    if (colour_kept) {
        colour_kept = false;
        (void)send_and_pause(kept_colour);
    } else {
        pausing = false;
    }
}
