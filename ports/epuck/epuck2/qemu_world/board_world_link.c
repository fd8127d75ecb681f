/* The e-puck2 image under QEMU as a robot of the world simulator: the
 * device layer's lower layer (ports/epuck/src/epuck_board.h) speaks the
 * world link (openswarm/epuck_world_link.h) over QEMU's own standard input
 * and output - which the world's controller script connects to the world -
 * through semihosting (world_link_io.h), so the same image that runs alone
 * in QEMU drives a body in the world. Its CPU's time is accounted
 * (cpu_account.h): the link's own work apart from the robot's.
 *
 * Lockstep: the world's steps are counted in the kernel's ticks. When a
 * step's advance_ms ticks have run (the kernel's time reaches
 * cortex_m4_tick_hook_ms, which tickless idle wakes for), the tick
 * interrupt answers with the
 * robot's outputs and, with SysTick stopped, waits for the next step's
 * inputs (the robot is frozen meanwhile, as between two world steps),
 * delivers them to the devices and starts SysTick again. Nothing else
 * runs meanwhile, so the guest's instructions stay the same whatever the
 * host's speed and runs repeat.
 *
 * One difference from the host build (ports/epuck/host): the first answer
 * is given at the first tick, so this robot's clock reads 1 ms more than
 * the host build's at every step. */
#include "../../src/epuck_board.h"
#include "../qemu/board_qemu.h"
#include "../qemu/semihosting.h"
#include "cpu_account.h"
#include "world_link_io.h"
#include "openswarm/cortex_m4.h"
#include "openswarm/epuck_world_link.h"
#include "openswarm/system_time.h"
#include "world_outputs.h"

#include <stddef.h>
#include <string.h>

#define SYST_CSR (*(volatile uint32_t *)0xE000E010u)
#define SYST_CVR (*(volatile uint32_t *)0xE000E018u)
#define SCB_ICSR (*(volatile uint32_t *)0xE000ED04u)
#define SCB_ICSR_PENDSTCLR (1u << 25)

static uint32_t link_since; /* when the link's own work (not the robot's) began */
static int last_selector = -1;
static uint16_t frame[WORLD_LINK_MAX_PIXELS];

static void answer(void) {
    epuck_world_output out;
    world_outputs_fill(&out);
    world_link_send(&out, sizeof out);
}

/* One step's inputs, delivered as the real board's interrupts would. */
static void take_inputs(void) {
    epuck_world_input in;
    world_link_read_input(&in, frame);
    uint32_t pixels = (uint32_t)in.frame_width * in.frame_height;
    if (in.flags & EPUCK_LINK_STOP) {
        cpu_account_report(true);
        answer();
        epuck_world_losses losses;
        world_outputs_losses(&losses);
        world_link_send(&losses, sizeof losses);
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
    cortex_m4_tick_hook_ms = Sys_Get_SystemTime() + in.advance_ms; /* the step's last tick */
}

/* In the tick interrupt, after the kernel's tick. The first step ends at
 * the first tick (cortex_m4_tick_hook_ms 0). */
static void world_step(void) {
    if ((int32_t)(Sys_Get_SystemTime() - cortex_m4_tick_hook_ms) < 0) return;
    link_since = cpu_account_now();
    uint32_t running = SYST_CSR;
    SYST_CSR = 0;
    __asm__ __volatile__("cpsid i" ::: "memory");
    answer();
    for (;;) {
        take_inputs();
        if (cortex_m4_tick_hook_ms != Sys_Get_SystemTime()) break;
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
    world_link_open();
    cpu_account_start();
    cortex_m4_tick_hook = world_step;
}
