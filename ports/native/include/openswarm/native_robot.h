/* Between a native-mode robot and the simulator that runs it.
 *
 * In the native mode an app's own sources, the kernel and the robot's
 * board are compiled for the host into one shared object (the robot), and
 * the simulator (openswarm-sim, sim/src/native) runs many robots of it in
 * one process. Each robot's RAM - the shared object's .data and .bss - is
 * its own image, copied in before it runs and out after, so programs keep
 * plain globals. Its stacks are its own memory beside the image. Time is
 * virtual: the robot's code is compiled with a callback at every basic
 * block that charges the work in the robot's own CPU cycles
 * (native_cpu.c), so a spin on kilo_ticks lets time pass like a sleep does.
 *
 * The robot runs in windows of simulated time the simulator gives it
 * (openswarm_native_run). Everything that crosses between the two goes
 * through the robot's native_io, which the simulator owns and the robot
 * reaches through a pointer in its image: frames on their way in, frames
 * and motor changes and console text on their way out, the EEPROM, the
 * analog inputs. The simulator reads and empties the outbound parts after
 * each window, the robot fills them while it runs: they are never touched
 * by both at once. */
#ifndef OPENSWARM_NATIVE_ROBOT_H
#define OPENSWARM_NATIVE_ROBOT_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Changes whenever native_io or native_entry changes shape: the simulator
 * refuses a robot built against another. */
#define NATIVE_ROBOT_ABI 6

#define NATIVE_FRAME_BYTES 12
#define NATIVE_EEPROM_BYTES 1024
#define NATIVE_INBOX_ROOM 64   /* frames on their way to one robot */
#define NATIVE_SENT_ROOM 4     /* frames one robot sends in a window */
#define NATIVE_MOTOR_ROOM 32   /* motor changes in a window */
#define NATIVE_CONSOLE_ROOM 2048
#define NATIVE_FAULT_ROOM 8
#define NATIVE_THREAD_NAMES 16
#define NATIVE_HANDLERS_SEEN 32 /* distinct handler functions noted as called */

/* The analog inputs, as the Kilobot's ADC numbers them (kilobot.h). */
enum { NATIVE_ADC_VOLTAGE = 6, NATIVE_ADC_LIGHT = 7, NATIVE_ADC_TEMPERATURE = 8, NATIVE_ADC_INPUTS = 9 };

/* A frame reaching this robot, at its own clock. */
typedef struct native_frame {
    uint64_t start; /* its first pulse: the receiver's interrupt */
    uint64_t end;   /* its last slot: the frame is whole */
    uint8_t bytes[NATIVE_FRAME_BYTES];
    int16_t low_gain, high_gain; /* the ADC's readings at its header */
    uint8_t damage;              /* enum native_frame_damage: the receiver drops it unless whole */
} native_frame;

/* What the receiver's decoder would make of a frame's pulses. */
enum native_frame_damage {
    NATIVE_FRAME_WHOLE = 0,
    NATIVE_FRAME_COLLIDED, /* another frame overlapped it, or a pulse came inside its header */
    NATIVE_FRAME_BROKEN    /* a pulse missing where one must be (--faults flip, cut) */
};

/* A frame this robot sent: its first pulse at cycle at (its own clock). */
typedef struct native_sent {
    uint64_t at;
    uint8_t bytes[NATIVE_FRAME_BYTES];
} native_sent;

typedef struct native_motor_change {
    uint64_t at;
    uint8_t left, right;
} native_motor_change;

typedef struct native_fault {
    uint64_t at;
    uint8_t fault, pid;
} native_fault;

enum native_transmit {
    NATIVE_TRANSMIT_NONE = 0,
    NATIVE_TRANSMIT_ASKED,   /* by the robot, at its clock's now */
    NATIVE_TRANSMIT_CLEAR,   /* by the simulator: the frame goes out */
    NATIVE_TRANSMIT_BUSY     /* by the simulator: another robot in range is sending */
};

/* How a robot stands after a window. */
enum native_state {
    NATIVE_RUNNING = 0,
    NATIVE_STOPPED,    /* main returned or sim_exit: status holds the code */
    NATIVE_BOOTLOADER, /* the overhead controller's BOOT: on a robot, reprogramming */
    NATIVE_RESTART     /* kilobot_restart: the simulator boots it afresh, mark kept */
};

typedef struct native_io {
    /* ---- set by the simulator ---- */
    uint8_t eeprom[NATIVE_EEPROM_BYTES];
    uint16_t adc_mv[NATIVE_ADC_INPUTS]; /* millivolts at each input */
    uint8_t charging;                   /* on the charger (PD0 low) */
    uint64_t noise;                     /* the analog noise's generator, per robot */
    double noise_counts;                /* its sd in ADC counts */
    /* Frames on their way in, by start: the simulator appends at the tail,
     * the robot takes from the head once it has received it whole (a ring
     * of NATIVE_INBOX_ROOM). */
    native_frame inbox[NATIVE_INBOX_ROOM];
    unsigned inbox_head, inbox_count;
    uint16_t restart_mark; /* kilobot_restart's, kept across the restart */
    /* A board that takes its sensors whole, a step at a time (the e-puck:
     * openswarm/native_epuck.h), finds them here; NULL on a Kilobot. When
     * the simulator sets board_inputs, they reach the robot as its board's
     * interrupt at once (as soon as interrupts are on); the board clears it. */
    void *board;
    uint8_t board_inputs;

    /* ---- set by the robot, emptied by the simulator after each window ---- */
    native_sent sent[NATIVE_SENT_ROOM];
    unsigned n_sent;
    native_motor_change motors[NATIVE_MOTOR_ROOM];
    unsigned n_motors;
    native_fault faults[NATIVE_FAULT_ROOM];
    unsigned n_faults;
    char console[NATIVE_CONSOLE_ROOM];
    size_t console_len;
    /* A transmission asked for (the frame is the last of sent): the robot
     * yields, and the simulator, which knows what every robot in range has
     * sent up to that moment, says whether the channel is clear. */
    uint8_t transmit;                   /* enum native_transmit */
    /* ---- set by the robot, read by the simulator ---- */
    uint8_t led;                        /* the colour shown now, KILOBOT_RGB */
    uint8_t state;                      /* enum native_state */
    uint8_t status;                     /* NATIVE_STOPPED's exit code */
    uint64_t now;                       /* its clock after the window */
    uint64_t asleep_until;              /* 0: busy; else idle until this (UINT64_MAX: no interrupt due) */
    const void *resume_sp;              /* where its stack resumes: the simulator fetches it ahead */
    uint64_t frames_lost_inbox_full;    /* frames the inbox had no room for (the simulator counts) */
    char thread_name[NATIVE_THREAD_NAMES][24]; /* by pid slot, from sim_thread_name */
    /* Each handler function the kernel has called, once (PORT_HANDLER_CALLED);
     * full: more than the room, those past it not noted (none is judged). */
    uintptr_t handlers_called[NATIVE_HANDLERS_SEEN];
    unsigned n_handlers_called;
    uint8_t handlers_called_full;
} native_io;

/* What the robot exports (the simulator finds them by name). */
typedef struct native_entry {
    unsigned abi;            /* NATIVE_ROBOT_ABI */
    uint32_t cpu_hz;         /* the robot's nominal clock */
    size_t stack_pool_bytes; /* the kernel's stacks (0: none) */
    size_t main_stack_bytes; /* what main's stack should have */
    /* The kernel's counters (openswarm/fault.h's sys_stats) in the loaded
     * image: the simulator reads each robot's at the end for its warnings. */
    const void *kernel_stats;
    /* Power the loaded image up as a new robot whose clock reads now:
     * main() on main_stack, threads' stacks in pool. The image must be as
     * loaded (or a copy of it). */
    void (*boot)(native_io *io, void *main_stack, size_t main_stack_size, void *pool, uint64_t now);
    /* Run the loaded robot until its clock reaches until (its own cycles),
     * or it stops, or its outbound room is full (then run it again). */
    void (*run)(uint64_t until);
} native_entry;

/* void openswarm_native_describe(native_entry *out): the robot's entry. */
#define NATIVE_DESCRIBE_SYMBOL "openswarm_native_describe"
typedef void (*native_describe_fn)(native_entry *out);

#ifdef __cplusplus
}
#endif

#endif
