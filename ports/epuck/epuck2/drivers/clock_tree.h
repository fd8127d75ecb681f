/* The e-puck2's clock tree: its 24 MHz external clock (HSE, bypass: an
 * oscillator drives OSC_IN, not a crystal) through the main PLL to a
 * 168 MHz core, APB1 at 42 MHz and APB2 at 84 MHz, the flash at five wait
 * states. Every wait for the hardware is bounded: a clock that never
 * becomes ready is reported, not waited for forever. */
#ifndef EPUCK2_CLOCK_TREE_H
#define EPUCK2_CLOCK_TREE_H

#include <stdint.h>

typedef enum epuck2_clock_status {
    EPUCK2_CLOCKS_RUNNING,   /* the core runs at 168 MHz from the PLL */
    EPUCK2_CLOCKS_NO_HSE,    /* the external clock never became ready */
    EPUCK2_CLOCKS_NO_PLL,    /* the PLL never locked */
    EPUCK2_CLOCKS_NO_SWITCH, /* the core never switched to the PLL */
} epuck2_clock_status;

#define EPUCK2_HSE_HZ 24000000u
#define EPUCK2_CORE_HZ 168000000u
/* What the core runs on if the tree does not start: the internal 16 MHz
 * RC oscillator, the buses undivided (RM0090 6.2.2). */
#define EPUCK2_HSI_HZ 16000000u

/* Each wait gives up after this many reads of its flag: on the 16 MHz
 * internal clock the tree starts from, tens of milliseconds, where the
 * HSE needs a few and the PLL a fraction of one (RM0090 6.2, datasheet). */
#define EPUCK2_CLOCK_WAIT_POLLS 200000u

/* Starts the tree; on a failure the core stays on the internal clock with
 * the buses undivided, and the status says which clock never came. */
epuck2_clock_status epuck2_clock_tree_start(void);

/* The status as a sentence for the console. */
const char *epuck2_clock_status_text(epuck2_clock_status status);

#endif
