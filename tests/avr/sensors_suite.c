/* The analog sensors as HAL devices, read from the simulator's inputs
 * (--light, --voltage, --temperature in millivolts): each reading's event
 * and kilobot_sense's value, then tables that map the counts, a processor
 * that rejects, and periodic sampling. Printed on the console; ctest checks
 * the counts against the millivolts it passed. */
#include "openswarm/kernel.h"
#include "openswarm/kilobot.h"
#include "openswarm/kilobot_sim.h"

/* Written by the handler (system thread), read by the script thread. */
static volatile int16_t last_event_value;
static volatile uint8_t events_seen;
static volatile uint32_t last_event_ms;

static void print_int(int32_t v) {
    if (v < 0) {
        sim_putc('-');
        v = -v;
    }
    sim_put_uint((uint32_t)v);
}

static const char *name_P(sys_event_id event) {
    return event == KILOBOT_EVENT_LIGHT     ? PSTR("light")
           : event == KILOBOT_EVENT_VOLTAGE ? PSTR("voltage")
                                            : PSTR("temperature");
}

static bool on_reading(sys_pid pid, sys_event_id event, const sys_event_data *data) {
    (void)pid;
    (void)event;
    last_event_value = *(const int16_t *)data->value;
    last_event_ms = Sys_Get_SystemTime();
    events_seen++;
    return true;
}

/* "<sensor> event E sense S": what the handler got, what the call returned. */
static void sense_and_print(sys_device *sensor) {
    int16_t value = 0;
    uint8_t before = events_seen;
    sys_status st = kilobot_sense(sensor, &value);
    sim_puts_P(name_P(sensor->event));
    if (st != SYS_OK || events_seen != (uint8_t)(before + 1u)) {
        sim_puts_P(PSTR(" failed "));
        print_int(st);
    } else {
        sim_puts_P(PSTR(" event "));
        print_int(last_event_value);
        sim_puts_P(PSTR(" sense "));
        print_int(value);
    }
    sim_putc('\n');
}

/* Counts to millivolts against the 3.3 V AVcc. */
static const kilobot_table_point mv_points[] = {{0, 0}, {1023, 3300}};
static const kilobot_sensor_table millivolts = {mv_points, 2};
/* A falling segment into negative values. */
static const kilobot_table_point celsius_points[] = {{200, 50}, {300, 25}, {400, -10}};
static const kilobot_sensor_table celsius = {celsius_points, 3};
/* Tables wholly above and wholly below the battery's reading: clamped. */
static const kilobot_table_point high_points[] = {{1000, 4200}, {1023, 4300}};
static const kilobot_sensor_table above = {high_points, 2};
static const kilobot_table_point low_points[] = {{0, 1}, {900, 2}};
static const kilobot_sensor_table below = {low_points, 2};

static uint8_t reject_all(sys_device *dev, const void *in, uint8_t size, void *out, uint8_t cap) {
    (void)dev;
    (void)in;
    (void)size;
    (void)out;
    (void)cap;
    return 0;
}

static void check_rejection(void) {
    Sys_Set_Processor(&kilobot_light, reject_all, NULL);
    uint8_t before = events_seen;
    sys_status st = kilobot_sense(&kilobot_light, NULL);
    sim_puts_P(PSTR("rejected "));
    print_int(st == SYS_E_NOT_FOUND && events_seen == before ? (int32_t)kilobot_light.rejected
                                                             : -1);
    sim_puts_P(PSTR(" not a sensor "));
    print_int(kilobot_sense(&kilobot_led, NULL) == SYS_E_INVALID);
    sim_putc('\n');
}

/* "every E1 E2 ... stopped N": the times between periodic readings, then
 * how many came in the 100 ms after stopping. */
static void check_periodic(void) {
    Sys_Set_Processor(&kilobot_voltage, NULL, NULL);
    uint32_t start = Sys_Get_SystemTime();
    kilobot_sense_every(&kilobot_voltage, 30);
    sim_puts_P(PSTR("every"));
    for (uint8_t n = 0; n < 4; n++) {
        uint8_t before = events_seen;
        while (events_seen == before) Sys_Sleep(1);
        sim_putc(' ');
        print_int((int32_t)(last_event_ms - start));
        start = last_event_ms;
    }
    kilobot_sense_every(&kilobot_voltage, 0);
    uint8_t stopped_at = events_seen;
    Sys_Sleep(100);
    sim_puts_P(PSTR(" value "));
    print_int(last_event_value);
    sim_puts_P(PSTR(" stopped "));
    print_int((uint8_t)(events_seen - stopped_at));
    sim_putc('\n');
}

static void script(void *arg) {
    (void)arg;
    sense_and_print(&kilobot_light);
    sense_and_print(&kilobot_voltage);
    sense_and_print(&kilobot_temperature);
    Sys_Set_Processor(&kilobot_light, kilobot_linear_table, (void *)&millivolts);
    Sys_Set_Processor(&kilobot_temperature, kilobot_linear_table, (void *)&celsius);
    sense_and_print(&kilobot_light);
    sense_and_print(&kilobot_temperature);
    Sys_Set_Processor(&kilobot_voltage, kilobot_linear_table, (void *)&above);
    sense_and_print(&kilobot_voltage);
    Sys_Set_Processor(&kilobot_voltage, kilobot_linear_table, (void *)&below);
    sense_and_print(&kilobot_voltage);
    check_rejection();
    check_periodic();
    sim_exit(0);
}

int main(void) {
    Sys_Init_Kernel();
    if (kilobot_devices_init() != SYS_OK || kilobot_sensors_init() != SYS_OK) sim_exit(2);
    Sys_Subscribe_to_Event(KILOBOT_EVENT_LIGHT, SYS_PID_SYSTEM, on_reading, NULL);
    Sys_Subscribe_to_Event(KILOBOT_EVENT_VOLTAGE, SYS_PID_SYSTEM, on_reading, NULL);
    Sys_Subscribe_to_Event(KILOBOT_EVENT_TEMPERATURE, SYS_PID_SYSTEM, on_reading, NULL);
    Sys_Start_Process_Ex(script, NULL, 128, 0, NULL);
    Sys_Start_Kernel();
    Sys_Run_SystemThread();
    return 0;
}
