/* The Kilobot's analog inputs in the native mode: a conversion takes its
 * 104 us (13 ADC clocks at 125 kHz) and reads the input the simulator
 * set, plus the robot's own gaussian noise, as the exact mode's board
 * does (sim/src/board/analog_noise.c). */
#include "native_internal.h"

#include <math.h>

#include "devices/devices_internal.h"
#include "openswarm/kilobot.h"

#define CONVERSION_CYCLES 832u
#define AVCC_MV 3300.0
#define INTERNAL_REFERENCE_MV 1100.0 /* the temperature sensor's */

static double uniform(void) { return (double)(native_random() >> 11) / 9007199254740992.0; }

static double gaussian(void) {
    double u = uniform(), v = uniform();
    return sqrt(-2.0 * log(u > 0 ? u : 1e-300)) * cos(2.0 * M_PI * v);
}

/* Interrupts run during the conversion, as on the robot; a frame received
 * meanwhile took the ADC for its distance, and the reading is lost (-1),
 * as the exact mode's board loses it (ports/kilobot/src/devices/adc.c). */
int16_t kilobot_adc_read(uint8_t input) {
    uint32_t receptions = native_ir_receptions;
    native_wait_for_hardware(CONVERSION_CYCLES);
    if (receptions != native_ir_receptions) return -1;
    native_io *io = native_io_of_robot;
    if (input >= NATIVE_ADC_INPUTS) return 0;
    double reference = input == KILOBOT_ADC_TEMPERATURE ? INTERNAL_REFERENCE_MV : AVCC_MV;
    double counts = io->adc_mv[input] * 1024.0 / reference + io->noise_counts * gaussian();
    long c = lround(counts);
    return (int16_t)(c < 0 ? 0 : c > 1023 ? 1023 : c);
}
