/* Tells simulators which MCU and clock this ELF is built for: a .mmcu
 * section of tag-length-value records (1 = part name, 64 chars; 2 = clock
 * in Hz, 32-bit; 0 = end), the layout simavr reads. */
#include <stdint.h>

#define MMCU __attribute__((section(".mmcu"), used))

struct mmcu_name { uint8_t tag, len; char name[64]; } __attribute__((packed));
struct mmcu_u32 { uint8_t tag, len; uint32_t value; } __attribute__((packed));

#define STR2(x) #x
#define STR(x) STR2(x)

const struct mmcu_name mmcu_part MMCU = {1, sizeof(struct mmcu_name) - 2, STR(OPENSWARM_MCU_NAME)};
const struct mmcu_u32 mmcu_clock MMCU = {2, sizeof(struct mmcu_u32) - 2, F_CPU};
const uint8_t _mmcu[2] MMCU = {0, 0};
