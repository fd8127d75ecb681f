/* {{name}}: a hop-count gradient, written for the classic Kilobot API.
 * Robot 1 is the seed (gradient 0); every other robot takes one more than
 * the smallest value it hears, and forgets what it has not heard for two
 * seconds. The LED shows the value: red 0, green 1, blue 2, white 3 or more.
 * Each robot reports a new hop count on its serial port, "metric hops N",
 * which `openswarm metrics` and sweeps read (experiments/ir_loss.json). */
#include <kilolib.h>
#include <debug.h>

#define SEED_UID 1
#define UNKNOWN 255
#define FORGET_TICKS (2 * TICKS_PER_SEC)

message_t message;
uint8_t gradient = UNKNOWN;
uint8_t best_heard = UNKNOWN;
uint32_t last_heard;
uint8_t reported = UNKNOWN; /* the hop count printed last */

static void show(uint8_t g) {
    static const uint8_t colours[] = {RGB(3, 0, 0), RGB(0, 3, 0), RGB(0, 0, 3)};
    set_color(g == UNKNOWN ? RGB(0, 0, 0) : g < 3 ? colours[g] : RGB(3, 3, 3));
}

/* After the LED is set, and only when the count changes: a line takes the
 * serial port about 3 ms. */
static void report(uint8_t g) {
    if (g == UNKNOWN || g == reported) return;
    reported = g;
    printf("metric hops %u\n", g);
}

void setup(void) {
    debug_init();
    message.type = NORMAL;
    if (kilo_uid == SEED_UID) gradient = 0;
}

void loop(void) {
    if (kilo_uid != SEED_UID) {
        if (kilo_ticks - last_heard > FORGET_TICKS) best_heard = UNKNOWN;
        gradient = best_heard == UNKNOWN ? UNKNOWN : best_heard + 1;
    }
    message.data[0] = gradient;
    message.crc = message_crc(&message);
    show(gradient);
    report(gradient);
    delay(100);
}

message_t *message_tx(void) { return gradient == UNKNOWN ? 0 : &message; }

void message_rx(message_t *m, distance_measurement_t *d) {
    (void)d;
    if (m->data[0] < best_heard || kilo_ticks - last_heard > FORGET_TICKS) best_heard = m->data[0];
    last_heard = kilo_ticks;
}

int main(void) {
    kilo_init();
    kilo_message_rx = message_rx;
    kilo_message_tx = message_tx;
    kilo_start(setup, loop);
    return 0;
}
