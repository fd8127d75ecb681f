/* The Kilobot's devices as HAL modules. Call kilobot_devices_init() after
 * Sys_Init_Kernel(); then send the events below (from threads, handlers or
 * interrupts), or replace a device's processor with Sys_Set_Processor. */
#ifndef OPENSWARM_KILOBOT_H
#define OPENSWARM_KILOBOT_H

#include "openswarm/kernel.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The LED colour: 2 bits per channel, as kilolib's RGB(r, g, b). */
#define KILOBOT_RGB(r, g, b) ((uint8_t)(((r)&3) | (((g)&3) << 2) | (((b)&3) << 4)))
/* data: one uint8_t colour */
#define KILOBOT_EVENT_LED SYS_EVENT_PORT_FIRST
/* data: kilobot_motors (raw duties) or one kilobot_motion byte */
#define KILOBOT_EVENT_MOTORS ((sys_event_id)(SYS_EVENT_PORT_FIRST + 1))

/* PWM duty of the two vibration motors, 0 (off) .. 255 (full). */
typedef struct kilobot_motors {
    uint8_t left;
    uint8_t right;
} kilobot_motors;

/* IR messages. A frame is 12 bytes on the wire: 9 data, 1 type, CRC-16
 * CCITT (seed 0xFFFF) over the first 10, little-endian. */
#define KILOBOT_IR_FRAME_BYTES 12
/* data: kilobot_ir_rx (a frame whose CRC checked, and how it was heard) */
#define KILOBOT_EVENT_IR_RX ((sys_event_id)(SYS_EVENT_PORT_FIRST + 2))
/* data: 10 bytes (9 data + type) to transmit; the Tx processor adds the CRC */
#define KILOBOT_EVENT_IR_TX ((sys_event_id)(SYS_EVENT_PORT_FIRST + 3))

/* Packed: 17 bytes on the host too (the native mode), as the kernel's
 * pools are sized for the robot's (the AVR aligns nothing anyway). */
typedef struct __attribute__((packed)) kilobot_ir_rx {
    uint8_t frame[KILOBOT_IR_FRAME_BYTES];
    int16_t low_gain;    /* ADC1 at the header's stop pulse */
    int16_t high_gain;   /* ADC0 at the start pulse */
    uint8_t distance_mm; /* the sender's distance; 0 unless kilobot_ir_with_distance ran */
} kilobot_ir_rx;

extern sys_device kilobot_ir;

/* The IR device's Rx processors: kilobot_ir_check_crc (the default) passes
 * the frames whose CRC checks; kilobot_ir_with_distance also turns the two
 * gain readings into the sender's distance in millimetres, through this
 * robot's calibration tables in EEPROM. Install with
 *   Sys_Set_Processor(&kilobot_ir, kilobot_ir_with_distance, NULL); */
uint8_t kilobot_ir_check_crc(sys_device *dev, const void *in, uint8_t size, void *out,
                             uint8_t capacity);
uint8_t kilobot_ir_with_distance(sys_device *dev, const void *in, uint8_t size, void *out,
                                 uint8_t capacity);
/* The same estimate from two gain readings (kilolib's estimate_distance). */
uint8_t kilobot_ir_distance_mm(int16_t low_gain, int16_t high_gain);

/* IR statistics: frames sent; received (delivered as KILOBOT_EVENT_IR_RX);
 * refused (whole and with a good CRC, but the kernel had no room: its
 * event queue or data pool was full, counted there too); rejected (bad
 * CRC); broken (cut short, without their header's stop pulse, or with
 * pulses past their end); collisions seen (a pulse inside a header);
 * transmissions deferred because the channel was busy. Each stops at 65535
 * rather than wrapping to 0. */
typedef struct kilobot_ir_stats {
    uint16_t sent, received, refused, bad_crc, broken, collisions, busy;
} kilobot_ir_stats;
void kilobot_ir_get_stats(kilobot_ir_stats *stats);

/* Send a 12-byte frame now (interrupts masked for its 4.4 ms). SYS_E_QUEUE_FULL
 * if the channel is busy (a reception in progress): try again later. */
sys_status kilobot_ir_transmit(const uint8_t frame[KILOBOT_IR_FRAME_BYTES]);

/* CRC-16 CCITT, seed 0xFFFF, over n bytes. */
uint16_t kilobot_crc(const uint8_t *bytes, uint8_t n);

/* Hardware-independent motion commands. The motors' default post-processor
 * (kilobot_motor_commands) turns them into this robot's calibrated duties. */
typedef enum kilobot_motion {
    KILOBOT_STOP = 0,
    KILOBOT_FORWARD,
    KILOBOT_TURN_LEFT,
    KILOBOT_TURN_RIGHT
} kilobot_motion;

/* Duties that make this robot turn or go straight (from its EEPROM). */
typedef struct kilobot_calibration {
    uint8_t turn_left, turn_right, straight_left, straight_right;
} kilobot_calibration;
extern kilobot_calibration kilobot_calib;
/* Read kilobot_calib from the EEPROM (again, after calibration rewrote it). */
void kilobot_calibration_load(void);
/* Write kilobot_calib and uid to the EEPROM (only the bytes that change,
 * 3.4 ms each: not from an interrupt). */
void kilobot_calibration_save(uint16_t uid);

/* Post-processor: a motion byte becomes calibrated duties, two bytes pass. */
uint8_t kilobot_motor_commands(sys_device *dev, const void *in, uint8_t size, void *out,
                               uint8_t capacity);

/* Safety post-processor: as kilobot_motor_commands, and a motor left at
 * full power longer than limit_ms (spin-up is all a vibration motor needs)
 * drops to fallback. Install with
 *   Sys_Set_Processor(&kilobot_motor_pair, kilobot_spinup_limited, &limit). */
typedef struct kilobot_spinup_limit {
    uint16_t limit_ms;
    uint8_t fallback;
} kilobot_spinup_limit;
uint8_t kilobot_spinup_limited(sys_device *dev, const void *in, uint8_t size, void *out,
                               uint8_t capacity);

extern sys_device kilobot_led;
extern sys_device kilobot_motor_pair;

/* Analog sensors: HAL input devices, registered by kilobot_sensors_init().
 * Each event's data is one int16_t: the reading after the device's
 * pre-processor (none by default: the ADC count 0..1023, what kilolib's
 * get_ambientlight, get_voltage and get_temperature return). */
#define KILOBOT_EVENT_LIGHT ((sys_event_id)(SYS_EVENT_PORT_FIRST + 4))       /* ADC7 */
#define KILOBOT_EVENT_VOLTAGE ((sys_event_id)(SYS_EVENT_PORT_FIRST + 5))     /* battery, ADC6 */
#define KILOBOT_EVENT_TEMPERATURE ((sys_event_id)(SYS_EVENT_PORT_FIRST + 6)) /* on chip */

extern sys_device kilobot_light;
extern sys_device kilobot_voltage;
extern sys_device kilobot_temperature;

/* Register the three sensors (and their events, 2 bytes each). Separate
 * from kilobot_devices_init so applications without them pay nothing. */
sys_status kilobot_sensors_init(void);

/* Read sensor now (about 110 us; in a thread with interrupts enabled, a
 * conversion the IR receiver takes over is done again), run its processor
 * and send its event; *value (may be NULL) receives the processed reading.
 * SYS_E_INVALID if sensor is not one of the three; SYS_E_NOT_FOUND if the
 * processor gave no value (counted in sensor->rejected); otherwise the
 * status of sending the event. */
sys_status kilobot_sense(sys_device *sensor, int16_t *value);

/* Read sensor every period ms from the 1 ms tick (the first period ms from
 * now), as kilobot_sense does; 0 stops. */
sys_status kilobot_sense_every(sys_device *sensor, uint16_t period);

/* Pre-processor: piecewise-linear interpolation through a table of (raw
 * ADC count, value) points, raw strictly increasing; readings below the
 * first point or above the last take its value. Install with
 *   static const kilobot_table_point lux_points[] = {{0, 0}, {800, 400}, {1023, 2000}};
 *   static const kilobot_sensor_table lux = {lux_points, 3};
 *   Sys_Set_Processor(&kilobot_light, kilobot_linear_table, (void *)&lux); */
typedef struct kilobot_table_point {
    int16_t raw;
    int16_t value;
} kilobot_table_point;
typedef struct kilobot_sensor_table {
    const kilobot_table_point *points;
    uint8_t count; /* at least 1 */
} kilobot_sensor_table;
uint8_t kilobot_linear_table(sys_device *dev, const void *in, uint8_t size, void *out,
                             uint8_t capacity);

/* Register the LED and the motors (and their events). */
sys_status kilobot_devices_init(void);

/* ---- the overhead controller, for apps on the OpenSwarm API ----
 * Its system messages (IR frames whose type, byte 9, is 0x80 or more) are
 * the robot's, not the app's: BOOT enters the IR bootloader, RESET starts
 * the program afresh, SLEEP, WAKEUP (KiloGUI's "pause"), CHARGE and
 * VOLTAGE hold it (motors off; the LED dark while asleep, the battery
 * level for VOLTAGE, as kilobot_battery_light shows it, dim blue
 * otherwise) until RUN starts it afresh. CALIB and READUID (KiloGUI's
 * calibration panel) hold it calibrating: the robot moves with the duties
 * being tuned (a 15 ms kick at full duty first; the same request again
 * changes nothing), or, for READUID, turns left if the uid bit asked for
 * is 1; SAVE writes the uid and the duties to the EEPROM and the robot
 * waits, dim blue, until RUN starts the app afresh with them (in
 * kilobot_calib and kilobot_uid()); RUN or RESET without SAVE leaves the
 * EEPROM as it was. Calibrating needs the clock event (OS_CFG_CLOCK_EVENT,
 * on by default): without it the robot stands still. The bootloader's own
 * messages are dropped. robot_devices_init() starts it (robot.h); kilolib
 * apps have their own (kilolib's overhead_controller.c). */
#define KILOBOT_MESSAGE_SYSTEM 0x80u /* the first system message type */
/* The system message types, as the classic library's message.h has them. */
enum kilobot_system_message {
    KILOBOT_MESSAGE_BOOT = 0x80,
    KILOBOT_MESSAGE_BOOTPGM_PAGE,
    KILOBOT_MESSAGE_BOOTPGM_SIZE,
    KILOBOT_MESSAGE_RESET,
    KILOBOT_MESSAGE_SLEEP,
    KILOBOT_MESSAGE_WAKEUP,
    KILOBOT_MESSAGE_CHARGE,
    KILOBOT_MESSAGE_VOLTAGE,
    KILOBOT_MESSAGE_RUN,
    KILOBOT_MESSAGE_READUID, /* data[0]: the uid bit asked for */
    KILOBOT_MESSAGE_CALIB    /* data: below */
};
/* CALIB's data: the mode, then every value KiloGUI's panel holds. */
enum kilobot_calib_mode {
    KILOBOT_CALIB_SAVE,
    KILOBOT_CALIB_UID,
    KILOBOT_CALIB_TURN_LEFT,
    KILOBOT_CALIB_TURN_RIGHT,
    KILOBOT_CALIB_STRAIGHT
};
enum kilobot_calib_data {
    KILOBOT_CALIB_AT_MODE = 0,
    KILOBOT_CALIB_AT_UID = 1, /* little-endian uint16_t */
    KILOBOT_CALIB_AT_TURN_LEFT = 3,
    KILOBOT_CALIB_AT_TURN_RIGHT = 4,
    KILOBOT_CALIB_AT_STRAIGHT_LEFT = 5,
    KILOBOT_CALIB_AT_STRAIGHT_RIGHT = 6
};
/* The battery level a voltage reading (ADC6, 0..1023) shows on the LED,
 * as the classic library's VOLTAGE does: green full, blue good, yellow
 * low, red nearly empty. */
uint8_t kilobot_battery_light(int16_t reading);
/* Whether the charger is charging the battery (it pulls PD0 low). */
bool kilobot_charging(void);
/* After the devices: acts on a restart that asked for a hold (and then
 * never returns: the kernel runs the held robot), else takes the system
 * messages from now on. */
void kilobot_overhead_control_start(void);
/* For the IR device's Rx processors: a system message the overhead
 * control took (true: no KILOBOT_EVENT_IR_RX for it). */
bool kilobot_overhead_control_take(const uint8_t frame[KILOBOT_IR_FRAME_BYTES]);

/* The overhead controller's messages as events, for an app that handles
 * them itself (robot.h: KILOBOT_OVERHEAD_CONTROL_EVENTS; openswarm.json:
 * "kilobot": {"overhead_controller": "events"}). While the app runs, each
 * system message but BOOT and the bootloader's own becomes a
 * KILOBOT_EVENT_OHC, sent from the IR interrupt, and the port does nothing
 * more: a handler acts on it, and hands what it does not handle itself to
 * kilobot_overhead_control_act, the port's action for it (a message not
 * handed on is vetoed). BOOT always enters the bootloader, so KiloGUI can
 * reprogram the robot whatever the app does; once held (SLEEP, WAKEUP,
 * CHARGE, VOLTAGE or calibrating, by the port's action) nothing of the app
 * runs and the port answers alone until RUN starts the app afresh.
 * The event's id is the one kilolib keeps for its own calls: a program has
 * one overhead controller, kilolib's or the port's. */
#define KILOBOT_EVENT_OHC ((sys_event_id)(SYS_EVENT_PORT_FIRST + 7))
/* data: the frame's first 10 bytes, as kilolib's message_t lays them out */
typedef struct kilobot_ohc_message {
    uint8_t data[9];
    uint8_t type; /* enum kilobot_system_message */
} kilobot_ohc_message;
/* Registers KILOBOT_EVENT_OHC (10 bytes), then kilobot_overhead_control_start
 * with the messages going to it: the registration's status. */
sys_status kilobot_overhead_control_start_events(void);
/* The port's action for a message of KILOBOT_EVENT_OHC, as without events:
 * RESET, a hold or calibrating restart the robot (and do not return),
 * RUN while the app runs does nothing. */
void kilobot_overhead_control_act(const kilobot_ohc_message *message);

/* The ways out of a program: the IR bootloader (at 0x7000), and a restart
 * from scratch (peripherals as at power-up, then address 0) that leaves the
 * next run a mark, read (and cleared) by kilobot_restart_mark: 0 after
 * power-up. */
void kilobot_enter_bootloader(void) __attribute__((noreturn));
void kilobot_restart(uint16_t mark) __attribute__((noreturn));
uint16_t kilobot_restart_mark(void);

/* Called every 1 ms from the tick interrupt (NULL: nothing). While it is
 * set the robot keeps the tick when it idles (no tickless idle): a clock
 * that only counts time does better with kilobot_elapsed_hook. Set it
 * before Sys_Start_Kernel or with interrupts masked: the tick must not
 * read half a pointer. (Not volatile: the tick reads it afresh each time,
 * and link-time optimisation drops the test from images that never set it.) */
extern void (*kilobot_tick_hook)(void);

/* Called in interrupt context with the milliseconds that have passed: 1 at
 * each tick; after a tickless sleep (OS_CFG_TICKLESS), all the sleep's at
 * once, when the robot wakes and before any thread or handler runs. For
 * clocks an application keeps, such as kilolib's kilo_ticks: they stay
 * exact, and the robot still sleeps through the milliseconds nothing else
 * needs. NULL: nothing. Set it as kilobot_tick_hook. */
extern void (*kilobot_elapsed_hook)(uint16_t ms);

/* Calibration and identity the robot keeps in its EEPROM. */
#define KILOBOT_EEPROM_OSCCAL 0x01
#define KILOBOT_EEPROM_TURN_LEFT 0x05
#define KILOBOT_EEPROM_TURN_RIGHT 0x09
#define KILOBOT_EEPROM_STRAIGHT_LEFT 0x0C
#define KILOBOT_EEPROM_STRAIGHT_RIGHT 0x14
#define KILOBOT_EEPROM_UID 0xB0 /* little-endian uint16_t */
/* printf and puts to the debug serial port (38400 baud, 8N1 on PD1; the
 * simulator prints its lines like the console). */
void kilobot_console_init(void);

/* The robot's own id, as KiloGUI set it (EEPROM 0xB0; 0xFFFF erased). */
uint16_t kilobot_uid(void);

/* The lower layers, for code that bypasses events (interrupts, kilolib). */
void kilobot_led_apply(uint8_t rgb);
void kilobot_motors_apply(uint8_t left, uint8_t right);

/* ADC inputs: the distance sensors' two gains, the battery, the light
 * sensor and the MCU's temperature sensor (against the internal 1.1 V
 * reference; the others against AVcc). */
#define KILOBOT_ADC_IR_HIGH_GAIN 0u
#define KILOBOT_ADC_IR_LOW_GAIN 1u
#define KILOBOT_ADC_VOLTAGE 6u
#define KILOBOT_ADC_LIGHT 7u
#define KILOBOT_ADC_TEMPERATURE 8u
/* One conversion of input, 0..1023, or -1 if the ADC is busy: a
 * conversion (the IR receiver's or another reader's) is running, or the IR
 * receiver took the ADC over at a frame's start before the result came
 * (about 110 us, interrupts left as the caller had them). */
int16_t kilobot_adc_read(uint8_t input);

#ifdef __cplusplus
}
#endif

#endif
