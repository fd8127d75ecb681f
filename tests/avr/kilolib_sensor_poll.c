/* Does polling the sensors disturb IR reception? Robot 1 sends MESSAGES
 * numbered messages as fast as kilolib lets it; robot 2's loop reads the
 * light sensor and the battery (kilolib) without pause, robot 4's the light
 * sensor through the port's kilobot_sense, robot 3's nothing. All hear the
 * same frames, so each prints how many it heard (CRC checked), out of
 * order, and the nearest and farthest distance; and how many of its
 * readings were busy (-1) and how many were neither busy nor the value it
 * read before any frame (a reading mixed up with the IR receiver's).
 * Checked by ctest. */
#include <kilolib.h>
#include "debug.h"
#include "openswarm/kilobot.h"

#define MESSAGES 30
#define REPORT_AT (2 * TICKS_PER_SEC)
#define KILOLIB_POLLER 2
#define SENSE_POLLER 4

message_t message;
uint8_t sent, heard, last_seq, out_of_order;
uint8_t nearest = 255, farthest;
uint16_t busy, corrupt;
int16_t light_before, voltage_before;

void setup(void) {
    debug_init();
    kilo_tx_period = 1; /* a frame every tick (32.8 ms) */
    message.type = NORMAL;
    light_before = get_ambientlight();
    voltage_before = get_voltage();
}

/* Busy (-1) is counted apart; any other reading must be what the sensor
 * read at setup (the simulator's inputs are constant). */
static void check(int16_t reading, int16_t before) {
    if (reading == -1)
        busy++;
    else if (reading != before)
        corrupt++;
}

void loop(void) {
    if (kilo_ticks >= REPORT_AT) {
        printf("robot %u sent %u heard %u out-of-order %u at %u-%u mm busy %u corrupt %u\n",
               kilo_uid, sent, heard, out_of_order, nearest, farthest, busy, corrupt);
        for (;;) delay(1000);
    }
    if (kilo_uid == KILOLIB_POLLER) {
        check(get_ambientlight(), light_before);
        check(get_voltage(), voltage_before);
    } else if (kilo_uid == SENSE_POLLER) {
        int16_t light = -1;
        kilobot_sense(&kilobot_light, &light);
        check(light, light_before);
    }
}

message_t *message_tx(void) {
    if (kilo_uid != 1 || sent == MESSAGES) return 0;
    message.data[0] = (uint8_t)(sent + 1u);
    message.crc = message_crc(&message);
    return &message;
}

void message_tx_success(void) { sent++; }

void message_rx(message_t *m, distance_measurement_t *d) {
    uint8_t mm = estimate_distance(d);
    if (mm < nearest) nearest = mm;
    if (mm > farthest) farthest = mm;
    if (m->data[0] != (uint8_t)(last_seq + 1u)) out_of_order++;
    last_seq = m->data[0];
    heard++;
}

int main(void) {
    kilo_init();
    kilobot_sensors_init();
    kilo_message_rx = message_rx;
    kilo_message_tx = message_tx;
    kilo_message_tx_success = message_tx_success;
    kilo_start(setup, loop);
    return 0;
}
