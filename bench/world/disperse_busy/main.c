/* The disperse template's behaviour written as classic kilolib programs
 * usually are: loop() never sleeps, it polls kilo_ticks to time its moves,
 * so the CPU is busy all the time (the simulator's worst case). Too close
 * to a neighbour (under 60 mm): turn a random way for a random time, walk
 * on for 2 s (LED red); otherwise stay (green). */
#include <kilolib.h>

#define TOO_CLOSE_MM 60
#define FORGET_TICKS TICKS_PER_SEC
#define WALK_TICKS (2 * TICKS_PER_SEC)

enum { RESTING, TURNING, WALKING };

message_t message;
uint8_t nearest_mm = 255;
uint32_t last_heard, move_until;
uint8_t state = RESTING;

void setup(void) {
    message.type = NORMAL;
    message.data[0] = (uint8_t)kilo_uid;
    message.crc = message_crc(&message);
}

static void turn(void) {
    set_color(RGB(3, 0, 0));
    spinup_motors();
    if (rand_soft() & 1)
        set_motors(kilo_turn_left, 0);
    else
        set_motors(0, kilo_turn_right);
    move_until = kilo_ticks + 8 + (rand_soft() & 0x1F); /* 0.25 to 1.3 s */
    state = TURNING;
}

void loop(void) {
    if (kilo_ticks - last_heard > FORGET_TICKS) nearest_mm = 255;
    if (state == TURNING && kilo_ticks >= move_until) {
        spinup_motors();
        set_motors(kilo_straight_left, kilo_straight_right);
        move_until = kilo_ticks + WALK_TICKS;
        state = WALKING;
    } else if (state != TURNING && kilo_ticks >= move_until) {
        if (nearest_mm < TOO_CLOSE_MM) {
            turn();
        } else if (state != RESTING) {
            set_color(RGB(0, 3, 0));
            set_motors(0, 0);
            state = RESTING;
        }
    }
}

message_t *message_tx(void) { return &message; }

void message_rx(message_t *m, distance_measurement_t *d) {
    (void)m;
    uint8_t mm = estimate_distance(d);
    if (mm < nearest_mm || kilo_ticks - last_heard > FORGET_TICKS) nearest_mm = mm;
    last_heard = kilo_ticks;
}

int main(void) {
    kilo_init();
    kilo_message_rx = message_rx;
    kilo_message_tx = message_tx;
    kilo_start(setup, loop);
    return 0;
}
