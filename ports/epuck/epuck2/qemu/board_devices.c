/* The e-puck's devices as the QEMU board has them (ports/epuck/src/
 * epuck_board.h): QEMU models none of the e-puck2's (no GPIO, no ESP32,
 * no camera), so what the robot would show - its LEDs, its wheels'
 * speeds - becomes records on the console (board_record.h) that
 * `openswarm run` shows; the selector is where the run's --selector=N put
 * it (semihosting arguments); proximity and camera give nothing. */
#include "../../src/epuck_board.h"
#include "openswarm/robot.h"
#include "board_record.h"
#include "board_qemu.h"

void epuck_board_set_wheels(int16_t left, int16_t right) {
    int32_t speeds[2] = {left, right};
    board_record("wheels", speeds, 2);
}

void epuck_board_set_ring_leds(uint8_t mask) {
    int32_t value = mask;
    board_record("ring", &value, 1);
}

void epuck_board_set_body_led(bool on) {
    int32_t value = on;
    board_record("body", &value, 1);
}

void epuck_board_set_front_led(bool on) {
    int32_t value = on;
    board_record("front", &value, 1);
}

void epuck_board_set_rgb_leds(uint8_t rgb) {
    int32_t channels[3] = {rgb & 3, (rgb >> 2) & 3, (rgb >> 4) & 3};
    board_record("led", channels, 3);
}

void epuck_board_start(void) { epuck_selector_arrived(board_selector_position); }

uint16_t epuck_robot_id(void) { return board_robot_id; }
