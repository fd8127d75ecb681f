/* The e-puck2 image under QEMU as a robot of the world simulator: the
 * device layer's lower layer (ports/epuck/src/epuck_board.h) speaks the
 * world link (openswarm/epuck_world_link.h) over QEMU's own standard input
 * and output - which the world's controller script connects to the world -
 * through semihosting, so the same image that runs alone in QEMU drives a
 * body in the world.
 *
 * Lockstep: the world's steps are counted in the kernel's ticks. When a
 * step's advance_ms ticks have run, the tick interrupt answers with the
 * robot's outputs and, with SysTick stopped, waits for the next step's
 * inputs (the robot is frozen meanwhile, as between two world steps),
 * delivers them to the devices and starts SysTick again. Nothing else
 * runs meanwhile, so the guest's instructions stay the same whatever the
 * host's speed and runs repeat.
 *
 * Why semihosting and not a serial port: QEMU's USART takes one byte per
 * pass of its main loop and wakes the CPU for each, about two host context
 * switches a byte; a step's inputs are 48 bytes and a camera frame 2400.
 * A semihosting read is one blocking read() of QEMU's for the whole
 * record, so a step costs QEMU one wake-up (docs/benchmarks.md, "The
 * e-puck2 image in the world").
 *
 * One difference from the host build (ports/epuck/host): the first answer
 * is given at the first tick, so this robot's clock reads 1 ms more than
 * the host build's at every step. */
#include "../../src/epuck_board.h"
#include "../qemu/board_qemu.h"
#include "../qemu/semihosting.h"
#include "cpu_account.h"
#include "openswarm/cortex_m4.h"
#include "openswarm/epuck_world_link.h"
#include "world_outputs.h"

#include <stddef.h>
#include <string.h>

#define SYST_CSR (*(volatile uint32_t *)0xE000E010u)
#define SYST_CVR (*(volatile uint32_t *)0xE000E018u)
#define SCB_ICSR (*(volatile uint32_t *)0xE000ED04u)
#define SCB_ICSR_PENDSTCLR (1u << 25)

/* The world's frames are 40 x 30 (docs/world.md); room for larger. */
#define MAX_PIXELS (80u * 60u)

static uint32_t ticks_left; /* of the current step; 0: answer at the next tick */
static uint32_t link_since; /* when the link's own work (not the robot's) began */
static int last_selector = -1;
static uint16_t frame[MAX_PIXELS];

static int32_t world_in = -1, world_out = -1; /* QEMU's standard input and output */

static void link_broken(const char *why) __attribute__((noreturn));

static void send(const void *data, size_t length) {
    if (!semihosting_write(world_out, data, (uint32_t)length)) link_broken("the world stopped reading");
}

/* A pipe's read may return part of a record: the rest follows. */
static void receive(void *data, size_t length) {
    uint8_t *p = data;
    for (size_t done = 0; done < length;) {
        uint32_t n = semihosting_read(world_in, p + done, (uint32_t)(length - done));
        if (n == 0) link_broken("the world closed the link mid-run");
        done += n;
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
        cpu_account_report();
        answer();
        epuck_world_losses losses;
        world_outputs_losses(&losses);
        send(&losses, sizeof losses);
        semihosting_exit(0);
    }
    cpu_account_add(CPU_LINK, link_since);
    uint32_t delivering = cpu_account_now();
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
    cpu_account_add(CPU_SENSORS, delivering);
    link_since = cpu_account_now();
    ticks_left = in.advance_ms;
}

/* In the tick interrupt, after the kernel's tick. */
static void world_step(void) {
    if (ticks_left > 1) {
        ticks_left--;
        return;
    }
    link_since = cpu_account_now();
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
    cpu_account_add(CPU_LINK, link_since);
}

/* The robot's index in the world: the world gives it to the controller
 * (OPENSWARM_ROBOT_ID), whose script hands it to the image as --id=N among
 * the semihosting arguments, which board_qemu.c reads. */
uint16_t epuck_robot_id(void) { return board_robot_id; }

void epuck_board_start(void) {
    world_in = semihosting_open("/dev/stdin", false);
    world_out = semihosting_open("/dev/stdout", true);
    if (world_in < 0 || world_out < 0)
        link_broken("cannot open QEMU's standard input and output: run QEMU with "
                    "-semihosting-config enable=on,target=native");
    cpu_account_start();
    cortex_m4_tick_hook = world_step;
}
