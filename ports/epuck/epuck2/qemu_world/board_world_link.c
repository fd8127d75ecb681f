/* The e-puck2 image under QEMU as a robot of the world simulator: the
 * device layer's lower layer (ports/epuck/src/epuck_board.h) speaks the
 * world link (openswarm/epuck_world_link.h) over USART2 - QEMU's second
 * serial port, which the world's controller script puts on its standard
 * input and output - so the same image that runs alone in QEMU drives a
 * body in the world.
 *
 * Lockstep: the world's steps are counted in the kernel's ticks. When a
 * step's advance_ms ticks have run, the tick interrupt answers with the
 * robot's outputs and, with SysTick stopped, waits for the next step's
 * inputs (the robot is frozen meanwhile, as between two world steps),
 * delivers them to the devices and starts SysTick again. Nothing else
 * runs meanwhile, so the guest's instructions stay the same whatever the
 * host's speed and runs repeat. The CPU sleeps for each byte (WFI with
 * interrupts masked by PRIMASK: USART2's receive interrupt wakes it and
 * is never taken), so QEMU waits for the world instead of spinning.
 *
 * One difference from the host build (ports/epuck/host): the first answer
 * is given at the first tick, so this robot's clock reads 1 ms more than
 * the host build's at every step. */
#include "../../src/epuck_board.h"
#include "../qemu/board_qemu.h"
#include "../qemu/semihosting.h"
#include "openswarm/cortex_m4.h"
#include "openswarm/epuck_world_link.h"
#include "world_outputs.h"

#include <stddef.h>
#include <string.h>

#define USART2_SR (*(volatile uint32_t *)0x40004400u)
#define USART2_DR (*(volatile uint32_t *)0x40004404u)
#define USART2_CR1 (*(volatile uint32_t *)0x4000440Cu)
#define USART_SR_RXNE (1u << 5)
#define USART_SR_TXE (1u << 7)
#define USART_CR1_UE (1u << 13)
#define USART_CR1_TE (1u << 3)
#define USART_CR1_RE (1u << 2)
#define USART_CR1_RXNEIE (1u << 5)
#define USART2_IRQ 38
#define NVIC_ICPR1 (*(volatile uint32_t *)0xE000E284u)

#define SYST_CSR (*(volatile uint32_t *)0xE000E010u)
#define SYST_CVR (*(volatile uint32_t *)0xE000E018u)
#define SCB_ICSR (*(volatile uint32_t *)0xE000ED04u)
#define SCB_ICSR_PENDSTCLR (1u << 25)

/* The world's frames are 40 x 30 (docs/world.md); room for larger. */
#define MAX_PIXELS (80u * 60u)

static uint32_t ticks_left; /* of the current step; 0: answer at the next tick */
static int last_selector = -1;
static uint16_t frame[MAX_PIXELS];

static void send(const void *data, size_t length) {
    const uint8_t *p = data;
    for (size_t i = 0; i < length; i++) {
        while ((USART2_SR & USART_SR_TXE) == 0) {
        }
        USART2_DR = p[i];
    }
}

static void receive(void *data, size_t length) {
    uint8_t *p = data;
    for (size_t i = 0; i < length; i++) {
        while ((USART2_SR & USART_SR_RXNE) == 0) __asm__ __volatile__("wfi");
        p[i] = (uint8_t)USART2_DR;
        NVIC_ICPR1 = 1u << (USART2_IRQ - 32);
    }
}

/* The link cannot go on (a message that is not one): say why, end the
 * run with status 2, as the host build does. */
static void link_broken(const char *why) {
    cortex_m4_print("epuck world link: ");
    cortex_m4_print(why);
    cortex_m4_print("\n");
    semihosting_exit(2);
}

static void answer(void) {
    epuck_world_output out;
    world_outputs_fill(&out);
    send(&out, sizeof out);
}

/* One step's inputs, delivered as the real board's interrupts would. */
static void take_inputs(void) {
    epuck_world_input in;
    receive(&in, sizeof in);
    if (in.magic != EPUCK_LINK_MAGIC) link_broken("an input that is not an e-puck link record");
    uint32_t pixels = (uint32_t)in.frame_width * in.frame_height;
    if (pixels > MAX_PIXELS) link_broken("a frame larger than 80 x 60");
    receive(frame, pixels * sizeof frame[0]);
    if (in.flags & EPUCK_LINK_STOP) {
        answer();
        epuck_world_losses losses;
        world_outputs_losses(&losses);
        send(&losses, sizeof losses);
        semihosting_exit(0);
    }
    if (in.selector != last_selector) {
        last_selector = in.selector;
        epuck_selector_arrived((uint8_t)in.selector);
    }
    if (in.flags & EPUCK_LINK_PROXIMITY) {
        epuck_proximity_samples samples;
        memcpy(samples.off, in.proximity_off, sizeof samples.off);
        memcpy(samples.pulsed, in.proximity_pulsed, sizeof samples.pulsed);
        epuck_proximity_arrived(&samples);
    }
    if (pixels != 0) {
        epuck_camera_frame f = {frame, in.frame_width, in.frame_height, 0};
        epuck_camera_arrived(&f);
    }
    ticks_left = in.advance_ms;
}

/* In the tick interrupt, after the kernel's tick. */
static void world_step(void) {
    if (ticks_left > 1) {
        ticks_left--;
        return;
    }
    uint32_t running = SYST_CSR;
    SYST_CSR = 0;
    __asm__ __volatile__("cpsid i" ::: "memory");
    answer();
    for (;;) {
        take_inputs();
        if (ticks_left != 0) break;
        answer(); /* an input of 0 ms: answered at once */
    }
    __asm__ __volatile__("cpsie i" ::: "memory");
    SCB_ICSR = SCB_ICSR_PENDSTCLR;
    SYST_CVR = 0;
    SYST_CSR = running;
}

/* The robot's index in the world: the world gives it to the controller
 * (OPENSWARM_ROBOT_ID), whose script hands it to the image as --id=N among
 * the semihosting arguments, which board_qemu.c reads. */
uint16_t epuck_robot_id(void) { return board_robot_id; }

void epuck_board_start(void) {
    USART2_CR1 = USART_CR1_UE | USART_CR1_TE | USART_CR1_RE | USART_CR1_RXNEIE;
    cortex_m4_irq_enable(USART2_IRQ, CORTEX_M4_PRIORITY_UNMASKED); /* to wake the CPU */
    cortex_m4_tick_hook = world_step;
}
