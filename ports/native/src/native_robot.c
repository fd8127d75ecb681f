/* A native robot's link to the simulator: powering up, running a window,
 * yielding back, stopping - and the one symbol the shared object exports
 * (openswarm/native_robot.h). */
#include "native_internal.h"

#include <string.h>

#include "openswarm/fault.h"

int main(void); /* the app's */
extern sys_stats os_stats; /* the kernel's counters (kernel/src/fault.c) */

native_io *native_io_of_robot;
static void *simulator_sp; /* the simulator's stack, while the robot runs */
static void *robot_sp;     /* the robot's, while the simulator runs */

static void main_entry(void *unused) {
    (void)unused;
    native_stop((uint8_t)main());
}

/* The loaded image is as the shared object was loaded: a robot that never
 * ran. Its clock starts at now (0, or where a restart happened). */
static void boot(native_io *io, void *main_stack, size_t size, void *pool, uint64_t now) {
    native_io_of_robot = io;
    native_stack_pool = pool;
    native_now = now;
    io->state = NATIVE_RUNNING;
    native_board_power_up();
    robot_sp = native_context_frame(main_stack, size, main_entry, NULL);
}

static void run(uint64_t until) {
    native_io *io = native_io_of_robot;
    io->asleep_until = 0;
    native_window(until); /* the inbox may hold new frames */
    native_switch(&simulator_sp, robot_sp);
    io->now = native_now;
    io->resume_sp = robot_sp;
}

/* Outputs changed with interrupts masked are told now, at the latest. */
void native_yield(void) {
    native_outputs_report();
    native_switch(&robot_sp, simulator_sp);
}

void native_make_room(const unsigned *count, unsigned room) {
    while (*count >= room) native_yield(); /* the simulator empties it, then runs us on */
}

void native_leave(uint8_t state) {
    native_io_of_robot->state = state;
    for (;;) native_yield(); /* never run again */
}

void native_stop(uint8_t status) {
    native_io_of_robot->status = status;
    native_leave(NATIVE_STOPPED);
}

/* Kernel faults go to the simulator, which prints them, as on any board. */
void port_report_fault(uint8_t fault, sys_pid pid) {
    native_io *io = native_io_of_robot;
    native_make_room(&io->n_faults, NATIVE_FAULT_ROOM);
    io->faults[io->n_faults++] = (native_fault){native_now, fault, pid};
}

/* xorshift64*, from the robot's own seed (native_io.noise). */
uint64_t native_random(void) {
    uint64_t x = native_io_of_robot->noise;
    x ^= x >> 12;
    x ^= x << 25;
    x ^= x >> 27;
    native_io_of_robot->noise = x;
    return x * 0x2545F4914F6CDD1Dull;
}

/* What the simulator needs to know of this robot (it calls this once, as
 * it loads the shared object): nothing of the image changes. */
__attribute__((visibility("default"))) void openswarm_native_describe(native_entry *out) {
    out->abi = NATIVE_ROBOT_ABI;
    out->cpu_hz = NATIVE_CPU_HZ;
    out->stack_pool_bytes = os_stack_pool_bytes;
    out->main_stack_bytes = NATIVE_MAIN_STACK_BYTES;
    out->kernel_stats = &os_stats;
    out->boot = boot;
    out->run = run;
}
