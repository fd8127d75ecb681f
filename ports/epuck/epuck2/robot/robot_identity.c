/* The robot's id: the STM32F407's 96-bit unique device id (RM0090 39.1,
 * at 0x1FFF7A10, set at the factory), folded to 16 bits by XOR of its six
 * halfwords. Two robots may share a folded id (1 in 65536 for a pair):
 * the id is for telling robots apart in logs, as the Kilobot's uid. */
#include "openswarm/robot.h"

#define UNIQUE_ID ((const volatile uint16_t *)0x1FFF7A10u)

uint16_t epuck_robot_id(void) {
    uint16_t id = 0;
    for (unsigned i = 0; i < 6u; i++) id ^= UNIQUE_ID[i];
    return id;
}
