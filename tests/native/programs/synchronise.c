/* synchronise, a classic kilolib program in the labs' style: every robot
 * flashes its LED white once a period (PERIOD kilo ticks, about 2 s) and
 * says where it is in its period. Each phase it hears pulls its own: at the
 * end of a period the robot moves its clock by half the mean difference
 * to what it heard. Robots that start at random phases end flashing
 * together (tests/native/crosscheck.py's synchronisation metric: how far
 * apart a flash is over the robots in the second half of the run). The phase goes out as late as
 * possible - message_tx writes it as the frame leaves - and the receiver
 * counts its own phase when the frame arrives, so the result rests on the
 * IR's timing: the modes' difference here is the native mode's window. */
#include <kilolib.h>

#define PERIOD 64 /* kilo ticks */
#define FLASH 3   /* ticks the LED is on */

message_t message;
uint32_t period_start;
uint32_t flash_until;
int32_t pull_sum;
uint8_t pulls;

int16_t my_phase(void) { return (int16_t)(kilo_ticks - period_start); }

void setup(void) {
    rand_seed(rand_hard());
    period_start = kilo_ticks - (rand_soft() % PERIOD); /* a random phase */
    message.type = NORMAL;
}

void loop(void) {
    if (my_phase() >= PERIOD) {
        /* A flash at every period's start, however the pull moved it. */
        flash_until = kilo_ticks + FLASH;
        period_start += PERIOD;
        /* Half the mean pull: all of it overshoots when both sides move. */
        if (pulls) period_start -= pull_sum / pulls / 2;
        pull_sum = 0;
        pulls = 0;
    }
    if (kilo_ticks < flash_until)
        set_color(RGB(3, 3, 3));
    else
        set_color(RGB(0, 0, 0));
    delay(10); /* a third of a tick: the robot sleeps instead of spinning */
}

message_t *message_tx(void) {
    message.data[0] = (uint8_t)my_phase();
    message.crc = message_crc(&message);
    return &message;
}

void message_rx(message_t *m, distance_measurement_t *d) {
    (void)d;
    int16_t difference = (int16_t)m->data[0] - my_phase();
    /* The nearer way round the period. */
    if (difference > PERIOD / 2) difference -= PERIOD;
    if (difference < -PERIOD / 2) difference += PERIOD;
    pull_sum += difference;
    pulls++;
}

int main(void) {
    kilo_init();
    kilo_message_rx = message_rx;
    kilo_message_tx = message_tx;
    kilo_start(setup, loop);
    return 0;
}
