/* avr-libc's CRC-CCITT update (reflected x^16 + x^12 + x^5 + 1), as the
 * Kilobot's wire format computes it on the host. */
#ifndef OPENSWARM_NATIVE_UTIL_CRC16_H
#define OPENSWARM_NATIVE_UTIL_CRC16_H

#include "../../../../kilobot/src/devices/ir_wire.h"

static inline uint16_t _crc_ccitt_update(uint16_t crc, uint8_t data) { return ir_wire_crc_step(crc, data); }

#endif
