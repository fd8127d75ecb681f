/* The e-puck's camera on the dsPIC: the PO3030K reset on RC13, identified
 * and set up over I2C for the classifier's frame (po3030k_setup.c), then
 * frames captured. Timer5 counts VSYNC (T5CK): each one starts a frame.
 * Timer4 counts HREF (T4CK): every href_per_row-th line its interrupt
 * (camera_capture.S, cycle-counted) reads a row's bytes where
 * camera_frame_row() says and calls board_camera_row_end. A whole frame
 * is handed to the device layer from the kernel's tick (board_camera_poll,
 * at most a millisecond later): the camera's own priority (6) is above the
 * kernel-aware interrupts and must not call the kernel. Left out of a
 * build with EPUCK_DSPIC_CAMERA 0 (board.h). */
#include "board.h"

#include <stddef.h>

#include "board_pins.h"
#include "camera_frame.h"
#include "dspic_compiler.h"
#include "dspic_port.h"
#include "i2c_master.h"
#include "po3030k_setup.h"
#include "../../src/epuck_board.h"
#include "p30f6014a_registers.h"

#if EPUCK_DSPIC_CAMERA

/* Read by camera_capture.S in its interrupt: where the row goes (NULL:
 * no row wanted), how many pixels, the NOPs between two taken pixels. */
uint8_t *volatile camera_row_destination;
uint16_t camera_row_columns;
uint16_t camera_row_delay;

static uint8_t href_per_row;
static const epuck_camera_frame *volatile ready; /* whole, not yet handed on */

/* The library holds reset low for a 100-pass loop; 200 NOPs here
 * (14 us), then as long again before the first I2C transfer. */
#define RESET_NOPS 200u

static void pause(void) {
    for (unsigned i = 0; i < RESET_NOPS; i++) DSPIC_NOP();
}

static void reset_sensor(void) {
    TRISC |= CAMERA_HREF_PIN | CAMERA_VSYNC_PIN | CAMERA_PCLK_PIN;
    TRISD |= CAMERA_DATA_PINS;
    LATC &= (uint16_t)~CAMERA_RESET_PIN;
    TRISC &= (uint16_t)~CAMERA_RESET_PIN;
    pause();
    LATC |= CAMERA_RESET_PIN;
    pause();
}

static bool is_po3030k(void) {
    uint8_t high, low;
    return dspic_i2c_read(PO3030K_ADDRESS, PO3030K_REG_ID_HIGH, &high) &&
           dspic_i2c_read(PO3030K_ADDRESS, PO3030K_REG_ID_LOW, &low) &&
           ((uint16_t)high << 8 | low) == PO3030K_ID;
}

static bool set_up(po3030k_capture *plan) {
    po3030k_write writes[PO3030K_SETUP_WRITES];
    if (!po3030k_plan(&po3030k_classifier_frame, writes, plan)) return false;
    for (unsigned i = 0; i < PO3030K_SETUP_WRITES; i++)
        if (!dspic_i2c_write(PO3030K_ADDRESS, writes[i].reg, writes[i].value)) return false;
    return true;
}

/* From the row interrupt (priority 6): the frame waits for the tick. */
static void frame_whole(const epuck_camera_frame *frame) { ready = frame; }

void board_camera_poll(void) {
    const epuck_camera_frame *frame = ready;
    if (frame == NULL) return;
    ready = NULL;
    epuck_camera_arrived(frame);
}

/* camera_capture.S, after a row: the next one, or Timer4 off until the
 * next VSYNC once the frame is whole. */
void board_camera_row_end(void);
void board_camera_row_end(void) {
    if (!camera_frame_row_done()) T4CON &= (uint16_t)~TCON_ON;
    camera_row_destination = camera_frame_row();
}

/* Each VSYNC: a frame starts; Timer4 counts from one HREF short of its
 * period, so the first line after VSYNC is read. */
DSPIC_ISR(_T5Interrupt);
DSPIC_ISR(_T5Interrupt) {
    IFS1 &= (uint16_t)~IRQ1_T5;
    TMR5 = 0;
    camera_frame_vsync();
    camera_row_destination = camera_frame_row();
    T4CON = 0;
    TMR4 = (uint16_t)(href_per_row - 1u);
    IFS1 &= (uint16_t)~IRQ1_T4;
    T4CON = TCON_ON | TCON_EXTERNAL;
}

static void set_priority(void) {
    IPC5 = (uint16_t)((IPC5 & ~((IPC_FIELD << IPC5_T4_SHIFT) | (IPC_FIELD << IPC5_T5_SHIFT))) |
                      (DSPIC_PRIORITY_CAMERA << IPC5_T4_SHIFT) | (DSPIC_PRIORITY_CAMERA << IPC5_T5_SHIFT));
}

/* Timer4: an interrupt every href_per_row HREFs (the interrupt clears
 * TMR4); Timer5: one every VSYNC (its interrupt clears TMR5). */
static void start_timers(void) {
    set_priority();
    T4CON = 0;
    PR4 = href_per_row;
    T5CON = 0;
    TMR5 = 0;
    PR5 = 1;
    IFS1 &= (uint16_t)~IRQ1_T4;
    IFS1 &= (uint16_t)~IRQ1_T5;
    IEC1 |= IRQ1_T4 | IRQ1_T5;
    T5CON = TCON_ON | TCON_EXTERNAL;
}

bool board_camera_start(void) {
    po3030k_capture plan;
    reset_sensor();
    dspic_i2c_init();
    if (!is_po3030k() || !set_up(&plan) ||
        !camera_frame_init(plan.columns, plan.rows, plan.columns, frame_whole)) {
        dspic_console_print("e-puck: no PO3030K camera answered on I2C; no frames\r\n");
        return false;
    }
    href_per_row = plan.href_per_row;
    camera_row_columns = plan.columns;
    camera_row_delay = plan.delay_repeat;
    camera_row_destination = NULL;
    start_timers();
    return true;
}

#endif
