/* The native robot's CPU: its virtual clock, interrupt mask and
 * interrupts, idle, and the work callback that makes time pass.
 *
 * The robot's code (app, kernel, board) is compiled with
 * -fsanitize-coverage=trace-pc: every basic block it enters calls
 * __sanitizer_cov_trace_pc, which charges NATIVE_CYCLES_PER_BLOCK of the
 * robot's cycles. When the clock reaches the next thing due - an
 * interrupt (the 1 ms tick, a frame's arrival) or the end of the window
 * the simulator gave - the callback takes it there, as the robot's CPU
 * would take an interrupt between two instructions. So a busy loop
 * advances time, deterministically, and a spin on kilo_ticks ends.
 *
 * This file and the rest of the port are compiled without the callback:
 * their own work is charged explicitly (native_spend), and nothing here
 * may be interrupted. All of it is the robot's own state: it lives in the
 * image the simulator swaps. */
#include "native_internal.h"

#include "openswarm/port.h"

uint64_t native_now;
uint8_t *native_stack_pool;

static uint64_t due;          /* the callback looks out of line from here on */
static uint64_t window_end;   /* where the simulator takes over */
static uint64_t next_tick;    /* the tick's next interrupt (while it runs) */
static uint8_t masked = 1;    /* the I flag, clear */
static uint8_t tick_stopped;  /* tickless: asleep with the tick off */
static uint64_t tick_deadline; /* tickless: the tick the kernel needs next */

/* What the robot's next interrupt is, and when: the receiver's comes at a
 * frame's first pulse, as the Kilobot's input capture does. */
static uint64_t next_frame_start(void) {
    const native_io *io = native_io_of_robot;
    return io->inbox_count != 0 ? io->inbox[io->inbox_head].start : UINT64_MAX;
}

static uint64_t interrupt_due(void) {
    if (native_io_of_robot->board_inputs) return native_now;
    uint64_t frame = next_frame_start();
    uint64_t tick = tick_stopped ? tick_deadline : next_tick;
    return frame < tick ? frame : tick;
}

/* After anything that changes the window, the mask or what is pending. */
void native_due_again(void) {
    uint64_t irq = masked ? UINT64_MAX : interrupt_due();
    due = irq < window_end ? irq : window_end;
}

void native_window(uint64_t end) {
    window_end = end;
    native_due_again();
}

/* The tick's interrupt, as the Kilobot port's: the quiet way when nothing
 * but the time and the slice need it. */
static void tick_interrupt(void) {
    next_tick += NATIVE_CYCLES_PER_TICK;
#if OS_CFG_QUIET_TICK
    if (!native_board_tick_hooked() && os_tick_quiet()) return;
#endif
    os_isr_enter();
    native_board_tick();
    os_isr_exit();
}

/* Everything due by now, oldest first, interrupts masked as an interrupt
 * runs (each may switch threads: we continue here when resumed). */
static void take_interrupts(void) {
    for (;;) {
        uint64_t frame = next_frame_start();
        uint64_t tick = tick_stopped ? UINT64_MAX : next_tick;
        if (native_io_of_robot->board_inputs) {
            native_io_of_robot->board_inputs = 0;
            native_board_inputs();
        } else if (frame <= native_now && frame <= tick) {
            native_ir_interrupt();
        } else if (tick <= native_now) {
            tick_interrupt();
        } else if (tick_stopped && tick_deadline <= native_now) {
            native_tickless_wake();
        } else {
            return;
        }
    }
}

/* Taken when interrupts come back on or the clock passes one: the board
 * looks at its outputs too (kilobot_motors_apply and friends end there). */
static void unmasked(void) {
    if (interrupt_due() <= native_now) {
        masked = 1;
        take_interrupts();
    }
    while (!native_outputs_report()) native_yield();
    masked = 0;
    native_due_again();
}

/* Out of line from the callback: the window's end, then interrupts. */
static void reached_due(void) {
    if (native_now >= window_end) native_yield();
    if (!masked && interrupt_due() <= native_now) unmasked();
    native_due_again();
}

/* The work callback: one basic block of the robot's code. */
void __sanitizer_cov_trace_pc(void) {
    native_now += NATIVE_CYCLES_PER_BLOCK;
    if (native_now >= due) reached_due();
}

/* With interrupts masked nothing reaches the robot meanwhile: the clock
 * may pass the window's end, and the simulator lets the robot be until the
 * others catch up (it yields once, after it). */
void native_spend(uint64_t cycles) {
    native_now += cycles;
    if (native_now >= due) reached_due();
}

/* Hardware running on its own while the CPU polls it (a character on the
 * serial port, a conversion, an EEPROM write): interrupts come when due,
 * and the time they take counts, as the hardware goes on meanwhile. */
void native_wait_for_hardware(uint64_t cycles) {
    uint64_t until = native_now + cycles;
    while (native_now < until) {
        if (due > native_now) native_now = due < until ? due : until;
        if (native_now >= due) reached_due();
    }
}

/* A loop that counts its own cycles (_delay_ms): interrupts come when
 * due, and the time they take does not count, so it ends later. */
void native_busy_loop(uint64_t cycles) {
    while (cycles != 0) {
        uint64_t room = due > native_now ? due - native_now : 0;
        uint64_t step = room < cycles ? room : cycles;
        native_now += step;
        cycles -= step;
        if (native_now >= due) reached_due();
    }
}

/* ---- the port's interrupt mask ---- */

port_irq_state_t port_irq_save(void) {
    port_irq_state_t was = masked;
    masked = 1;
    native_due_again();
    return was;
}

void port_irq_restore(port_irq_state_t state) {
    if (!state) port_irq_enable();
}

void port_irq_enable(void) { unmasked(); }

void port_irq_disable(void) {
    masked = 1;
    native_due_again();
}

uint8_t native_irq_masked(void) { return masked; }

/* ---- the tick and idle ---- */

void port_tick_start(void) {
    next_tick = (native_now / NATIVE_CYCLES_PER_TICK + 1) * NATIVE_CYCLES_PER_TICK;
    native_due_again();
}

/* Asleep until the next interrupt: the clock jumps there (in parts, at
 * each window's end: the simulator may bring a frame that comes first). */
static void sleep_until_interrupt(void) {
    for (;;) {
        uint64_t irq = interrupt_due();
        if (irq <= window_end) {
            if (irq > native_now) native_now = irq;
            return;
        }
        native_now = window_end;
        native_io_of_robot->asleep_until = irq;
        native_yield();
    }
}

void port_idle(void) {
    sleep_until_interrupt();
    take_interrupts();
}

/* The ticks slept, credited: the kernel's time first, then the app's clocks. */
void native_tickless_wake(void) {
    if (!tick_stopped) return;
    tick_stopped = 0;
    uint64_t ticks = native_now < next_tick ? 0 : (native_now - next_tick) / NATIVE_CYCLES_PER_TICK + 1;
    next_tick += ticks * NATIVE_CYCLES_PER_TICK;
    while (ticks != 0) {
        uint16_t part = ticks > 65535u ? 65535u : (uint16_t)ticks;
        ticks -= part;
        os_ticks_slept(part);
        native_board_elapsed(part);
    }
}

void port_tickless_wake(void) { native_tickless_wake(); }

void port_idle_for(uint32_t ticks) {
    if (ticks < 2u || native_board_tick_needed()) {
        port_idle();
        return;
    }
    tick_stopped = 1;
    tick_deadline = ticks == UINT32_MAX ? UINT64_MAX : next_tick + (uint64_t)(ticks - 1u) * NATIVE_CYCLES_PER_TICK;
    sleep_until_interrupt();
    take_interrupts();
}

/* ---- power-up ---- */

void port_init(void) {
    masked = 1;
    tick_stopped = 0;
    next_tick = UINT64_MAX; /* until port_tick_start */
    native_due_again();
}
