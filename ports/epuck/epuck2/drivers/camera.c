/* The e-puck2's camera. The DCMI takes the sensor's bytes (8 data lines,
 * sampled on PCLK's rising edge, HSYNC and VSYNC active low: the firmware's
 * DCMI set-up) in snapshot mode, one frame a capture, and packs them four
 * to a 32-bit word, the first byte lowest; DMA2 stream 1, channel 1, moves
 * the words to RAM through its FIFO. At transfer complete the frame is
 * whole: its bytes, high byte of each pixel first as the sensor sends them,
 * become RGB565 pixels in place and the frame is handed on. The next
 * capture starts into the same memory once both the frame has been handed
 * on and the DCMI has seen the frame end (its capture bit is then clear;
 * the two come in either order, the DMA's FIFO draining after the last
 * byte). An overrun or error loses bytes: that frame is dropped and the
 * DCMI restarted, to begin again at the next frame's start. Both
 * interrupts must have the same priority (neither preempts the other).
 * Facts: ports/epuck/README.md. */
#include "camera.h"

#include "po8030.h"
#include "stm32f4_registers.h"

#define FRAME_PIXELS (EPUCK2_CAMERA_WIDTH * EPUCK2_CAMERA_HEIGHT)
#define FRAME_WORDS (FRAME_PIXELS * 2u / 4u)
#define DMA_CHANNEL_DCMI 1u
#define AF_DCMI 13u
#define STREAM (&DMA2->S[1])
#define STREAM_FLAGS (DMA_FLAGS_ALL << DMA_STREAM1_SHIFT)
#define STOP_POLLS 1000u /* a stream stops within a word's transfer */

/* Words for the DMA, pixels for the frame, bytes for the conversion. */
static union {
    uint32_t words[FRAME_WORDS];
    uint16_t pixels[FRAME_PIXELS];
    uint8_t bytes[FRAME_PIXELS * 2u];
} memory;

static epuck2_camera_frame_done frame_done;
static volatile uint32_t dropped;
/* What the frame under way has done of HANDED_ON and ENDED. */
#define HANDED_ON 1u
#define ENDED 2u
static uint8_t frame_state;
static const epuck_camera_frame frame = {memory.pixels, EPUCK2_CAMERA_WIDTH, EPUCK2_CAMERA_HEIGHT, 0};

/* HSYNC PA4, PCLK PA6, D5 PB6, VSYNC PB7, D0 PC6, D1 PC7, D2 PE0, D3 PE1,
 * D4 PE4, D6 PE5, D7 PE6: all alternate function 13. */
static void dcmi_pins(void) {
    static const struct {
        stm32_gpio *port;
        uint8_t pin;
    } pins[] = {{GPIOA, 4}, {GPIOA, 6}, {GPIOB, 6}, {GPIOB, 7}, {GPIOC, 6}, {GPIOC, 7},
                {GPIOE, 0}, {GPIOE, 1}, {GPIOE, 4}, {GPIOE, 5}, {GPIOE, 6}};
    RCC_ENABLES->AHB1ENR |= RCC_AHB1ENR_GPIOAEN | RCC_AHB1ENR_GPIOBEN | RCC_AHB1ENR_GPIOCEN |
                            RCC_AHB1ENR_GPIOEEN;
    for (unsigned i = 0; i < sizeof pins / sizeof pins[0]; i++) stm32_gpio_af(pins[i].port, pins[i].pin, AF_DCMI);
}

/* The stream stopped (a stream's registers are written only then), its
 * flags cleared, a whole frame's words set to go. */
static void dma_reload(void) {
    STREAM->CR &= ~DMA_SxCR_EN;
    for (unsigned n = 0; (STREAM->CR & DMA_SxCR_EN) && n < STOP_POLLS; n++) STM32_POLL();
    DMA2->LIFCR = STREAM_FLAGS;
    STREAM->NDTR = FRAME_WORDS;
    STREAM->CR |= DMA_SxCR_EN;
}

static void capture_next(void) {
    frame_state = 0;
    DCMI->ICR = DCMI_IT_FRAME | DCMI_IT_OVR | DCMI_IT_ERR;
    dma_reload();
    DCMI->CR |= DCMI_CR_CAPTURE;
}

static void frame_did(uint8_t what) {
    frame_state |= what;
    if (frame_state == (HANDED_ON | ENDED)) capture_next();
}

/* Off and on: the DCMI drops the rest of the frame and waits for the next
 * one's start. */
static void drop_frame(void) {
    DCMI->CR &= ~(DCMI_CR_CAPTURE | DCMI_CR_ENABLE);
    DCMI->CR |= DCMI_CR_ENABLE;
    dropped++;
    capture_next();
}

/* The sensor's high byte first, in place: each pixel's two bytes are read
 * before its halfword is written. */
static void to_rgb565(void) {
    for (unsigned i = 0; i < FRAME_PIXELS; i++)
        memory.pixels[i] = (uint16_t)((unsigned)memory.bytes[2u * i] << 8 | memory.bytes[2u * i + 1u]);
}

void DMA2_Stream1_IRQHandler(void) {
    uint32_t flags = (DMA2->LISR >> DMA_STREAM1_SHIFT) & DMA_FLAGS_ALL;
    DMA2->LIFCR = flags << DMA_STREAM1_SHIFT;
    if (flags & (DMA_FLAG_TE | DMA_FLAG_DME)) {
        drop_frame();
        return;
    }
    if ((flags & DMA_FLAG_TC) == 0) return;
    /* An overrun whose own interrupt has not run yet: bytes are missing. */
    if (DCMI->RIS & (DCMI_IT_OVR | DCMI_IT_ERR)) {
        drop_frame();
        return;
    }
    to_rgb565();
    if (frame_done != 0) frame_done(&frame);
    frame_did(HANDED_ON);
}

void DCMI_IRQHandler(void) {
    uint32_t raised = DCMI->RIS & (DCMI_IT_FRAME | DCMI_IT_OVR | DCMI_IT_ERR);
    DCMI->ICR = raised;
    if (raised & (DCMI_IT_OVR | DCMI_IT_ERR))
        drop_frame();
    else if (raised & DCMI_IT_FRAME)
        frame_did(ENDED);
}

uint32_t epuck2_camera_frames_dropped(void) { return dropped; }

#ifdef EPUCK2_REGISTER_MODEL
uint8_t *epuck2_camera_model_dma_memory(void) { return memory.bytes; }
#endif

static void dma_setup(void) {
    RCC_ENABLES->AHB1ENR |= RCC_AHB1ENR_DMA2EN;
    STREAM->CR = 0;
    STREAM->PAR = (uint32_t)(uintptr_t)&DCMI->DR;
    STREAM->M0AR = (uint32_t)(uintptr_t)memory.words;
    /* Peripheral to memory, words both sides, the memory address moving,
     * not circular (a frame, then the driver re-arms), interrupts at the
     * end and on errors. */
    STREAM->CR = DMA_SxCR_CHSEL(DMA_CHANNEL_DCMI) | DMA_SxCR_PL_VERY_HIGH | DMA_SxCR_MSIZE_WORD |
                 DMA_SxCR_PSIZE_WORD | DMA_SxCR_MINC | DMA_SxCR_TCIE | DMA_SxCR_TEIE | DMA_SxCR_DMEIE;
    /* The FIFO absorbs the bus's latency between the DCMI's words. */
    STREAM->FCR = DMA_SxFCR_DMDIS | DMA_SxFCR_FTH_FULL;
}

bool epuck2_camera_init(epuck2_camera_frame_done on_frame) {
    frame_done = on_frame;
    dropped = 0;
    if (!epuck2_po8030_init()) return false;
    dcmi_pins();
    RCC_ENABLES->AHB2ENR |= RCC_AHB2ENR_DCMIEN;
    /* 8 data bits (EDM 00), every frame, no crop, no embedded syncs. */
    DCMI->CR = DCMI_CR_CM_SNAPSHOT | DCMI_CR_PCKPOL;
    DCMI->IER = DCMI_IT_FRAME | DCMI_IT_OVR | DCMI_IT_ERR;
    dma_setup();
    DCMI->CR |= DCMI_CR_ENABLE;
    capture_next();
    return true;
}
