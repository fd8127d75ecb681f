/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* The Kilobot IR frame's checksum, for the frames the simulator makes (the
 * overhead controller's) and those it reads off the air (--ir-log); worked
 * out here, apart from the firmware's avr-libc routine. */
#include "sim.h"

/* CRC-16 CCITT, reflected (x^16 + x^12 + x^5 + 1 as 0x8408), seed 0xFFFF,
 * bit by bit. */
uint16_t ir_frame_crc(const uint8_t *bytes) {
    uint16_t crc = 0xFFFF;
    for (int i = 0; i < IR_CRC_BYTES; i++) {
        crc ^= bytes[i];
        for (int b = 0; b < 8; b++) crc = (crc & 1u) ? (uint16_t)((crc >> 1) ^ 0x8408u) : (uint16_t)(crc >> 1);
    }
    return crc;
}
