/* A classic Kilobot program, unmodified, printing what estimate_distance
 * makes of gain readings with the tables in its EEPROM (the simulator's):
 * the readings robots measure at 35 to 100 mm, and the edges of the rules
 * (either gain alone, the blend between, past either table's end). The
 * classic library prints the same for the same tables. */
#include <kilolib.h>
#include "debug.h"

static const int16_t gains[][2] = {
    /* low, high: measured in the simulator from 35 to 100 mm */
    {437, 1021}, {382, 1021}, {340, 907}, {305, 817}, {254, 681},
    {218, 583}, {190, 510}, {169, 453}, {152, 408},
    /* closer than either table starts */
    {600, 1023}, {465, 700},
    /* the thresholds: high alone at 700, low alone at 900, blends between */
    {300, 700}, {300, 701}, {300, 800}, {300, 899}, {300, 900},
    /* past the tables' ends: high gain extrapolated, low gain not */
    {150, 300}, {100, 200}, {50, 100}, {10, 20}, {100, 800}, {100, 950},
};

void setup(void) {
    debug_init();
    for (uint8_t i = 0; i < sizeof gains / sizeof gains[0]; i++) {
        distance_measurement_t d = {gains[i][0], gains[i][1]};
        printf("low %d high %d mm %u\n", d.low_gain, d.high_gain, estimate_distance(&d));
    }
}

void loop(void) {}

int main(void) {
    kilo_init();
    kilo_start(setup, loop);
    return 0;
}
