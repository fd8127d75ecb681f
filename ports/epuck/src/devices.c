/* The e-puck's devices and their registration with the HAL. Each event is
 * registered at its value's size first, so the event data pool holds what
 * the values need, not the HAL's largest value for every one. */
#include "devices_internal.h"
#include "epuck_board.h"
#include "openswarm/port.h"

typedef char port_reserves_the_epuck_events[EPUCK_EVENT_COUNT <= PORT_EVENT_COUNT ? 1 : -1];

static void wheels_write(sys_device *dev, const void *raw, uint8_t size) {
    (void)dev;
    const epuck_wheel_speeds *s = raw;
    if (size == sizeof *s) epuck_board_set_wheels(s->left, s->right);
}

static uint8_t byte_of(const void *raw, uint8_t size) { return size >= 1 ? *(const uint8_t *)raw : 0; }

static void ring_write(sys_device *dev, const void *raw, uint8_t size) {
    (void)dev;
    epuck_board_set_ring_leds(byte_of(raw, size));
}
static void body_write(sys_device *dev, const void *raw, uint8_t size) {
    (void)dev;
    epuck_board_set_body_led(byte_of(raw, size) != 0);
}
static void front_write(sys_device *dev, const void *raw, uint8_t size) {
    (void)dev;
    epuck_board_set_front_led(byte_of(raw, size) != 0);
}
static void rgb_write(sys_device *dev, const void *raw, uint8_t size) {
    (void)dev;
    epuck_board_set_rgb_leds(byte_of(raw, size));
}

sys_device epuck_wheels = {"wheels", SYS_DEVICE_OUTPUT, EPUCK_EVENT_WHEELS, 0,
                           epuck_wheels_limited, NULL, wheels_write,
                           &epuck_wheel_default_limits, 0};
sys_device epuck_ring_leds = {"ring leds", SYS_DEVICE_OUTPUT, EPUCK_EVENT_RING_LEDS, 0, NULL, NULL,
                              ring_write, NULL, 0};
sys_device epuck_body_led = {"body led", SYS_DEVICE_OUTPUT, EPUCK_EVENT_BODY_LED, 0, NULL, NULL,
                             body_write, NULL, 0};
sys_device epuck_front_led = {"front led", SYS_DEVICE_OUTPUT, EPUCK_EVENT_FRONT_LED, 0, NULL, NULL,
                              front_write, NULL, 0};
sys_device epuck_rgb_leds = {"rgb leds", SYS_DEVICE_OUTPUT, EPUCK_EVENT_RGB_LEDS, 0, NULL, NULL,
                             rgb_write, NULL, 0};
sys_device epuck_proximity = {"proximity", SYS_DEVICE_INPUT, EPUCK_EVENT_PROXIMITY, 0,
                              epuck_proximity_reflection, NULL, NULL, NULL, 0};
sys_device epuck_camera = {"camera", SYS_DEVICE_INPUT, EPUCK_EVENT_CAMERA, 0,
                           epuck_camera_classifier, NULL, NULL, NULL, 0};
sys_device epuck_selector = {"selector", SYS_DEVICE_INPUT, EPUCK_EVENT_SELECTOR, 0,
                             epuck_selector_changes, NULL, NULL, NULL, 0};

static const struct {
    sys_device *device;
    uint8_t value_size;
} all[] = {
    {&epuck_wheels, sizeof(epuck_wheel_speeds)}, {&epuck_ring_leds, 1}, {&epuck_body_led, 1},
    {&epuck_front_led, 1}, {&epuck_rgb_leds, 1}, {&epuck_proximity, sizeof(epuck_proximity_reading)},
    {&epuck_camera, 1}, {&epuck_selector, 1},
};

sys_status epuck_devices_init(void) {
    epuck_wheels_forget();
    epuck_selector_forget();
    for (unsigned i = 0; i < sizeof all / sizeof all[0]; i++) {
        sys_status st = Sys_Register_Event_Sized(all[i].device->event, all[i].value_size);
        if (st == SYS_OK) st = Sys_Register_Device(all[i].device);
        if (st != SYS_OK) return st;
    }
    epuck_board_start();
    return SYS_OK;
}

void epuck_proximity_arrived(const epuck_proximity_samples *samples) {
    Sys_Device_Input(&epuck_proximity, samples, sizeof *samples);
}

void epuck_camera_arrived(const epuck_camera_frame *frame) {
    Sys_Device_Input(&epuck_camera, frame, sizeof *frame);
}

void epuck_selector_arrived(uint8_t position) {
    Sys_Device_Input(&epuck_selector, &position, sizeof position);
}
