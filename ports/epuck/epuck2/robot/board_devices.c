/* The e-puck's devices (ports/epuck/src/epuck_board.h) on the e-puck2's
 * drivers. Inputs arrive in the drivers' interrupts: each callback is
 * bracketed for the kernel (cortex_m4_isr_enter/exit), so the event it
 * sends is dispatched when the last interrupt ends. */
#include "../../src/epuck_board.h"
#include "board_robot.h"

#include "openswarm/cortex_m4.h"

#include "../drivers/camera.h"
#include "../drivers/esp32_link.h"
#include "../drivers/i2c_master.h"
#include "../drivers/leds.h"
#include "../drivers/proximity.h"
#include "../drivers/selector.h"
#include "../drivers/steppers.h"
#include "../drivers/stm32f4_registers.h"

void epuck_board_set_wheels(int16_t left, int16_t right) { epuck2_steppers_set(left, right); }
void epuck_board_set_ring_leds(uint8_t mask) { epuck2_leds_set_ring(mask); }
void epuck_board_set_body_led(bool on) { epuck2_leds_set_body(on); }
void epuck_board_set_front_led(bool on) { epuck2_leds_set_front(on); }

/* A failed exchange is counted by the driver (epuck2_esp32_failed_exchanges). */
void epuck_board_set_rgb_leds(uint8_t rgb) { (void)epuck2_esp32_set_rgb_leds(rgb); }

static void proximity_round(const epuck_proximity_samples *samples) {
    cortex_m4_isr_enter();
    epuck_proximity_arrived(samples);
    cortex_m4_isr_exit();
}

static void camera_frame(const epuck_camera_frame *frame) {
    cortex_m4_isr_enter();
    epuck_camera_arrived(frame);
    cortex_m4_isr_exit();
}

static void selector_read(uint8_t position) {
    cortex_m4_isr_enter();
    epuck_selector_arrived(position);
    cortex_m4_isr_exit();
}

/* Before the kernel runs: the outputs, quiet. */
void board_outputs_start(void) {
    epuck2_leds_init();
    epuck2_steppers_init();
    epuck2_esp32_link_init();
    cortex_m4_irq_enable(TIM3_IRQ, ROBOT_PRIORITY_STEPPERS);
    cortex_m4_irq_enable(TIM4_IRQ, ROBOT_PRIORITY_STEPPERS);
    cortex_m4_irq_enable(TIM6_DAC_IRQ, ROBOT_PRIORITY_ESP32);
}

/* Once the devices are registered: the inputs start. A camera that does
 * not answer leaves the robot without frames, not without the rest. */
void epuck_board_start(void) {
    epuck2_proximity_init(proximity_round);
    cortex_m4_irq_enable(TIM2_IRQ, ROBOT_PRIORITY_PROXIMITY);
    cortex_m4_irq_enable(ADC_IRQ, ROBOT_PRIORITY_PROXIMITY);
    epuck2_selector_init(selector_read);
    cortex_m4_irq_enable(TIM7_IRQ, ROBOT_PRIORITY_SELECTOR);
    epuck2_i2c_init();
    if (epuck2_camera_init(camera_frame)) {
        cortex_m4_irq_enable(DMA2_STREAM1_IRQ, ROBOT_PRIORITY_CAMERA);
        cortex_m4_irq_enable(DCMI_IRQ, ROBOT_PRIORITY_CAMERA);
    } else {
        cortex_m4_print("e-puck2: the camera did not answer on I2C1; no frames\n");
    }
}
