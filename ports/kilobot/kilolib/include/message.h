/* Kilobot messages, as the classic Kilobot library defines them: 12 bytes
 * on the wire, 9 of data, a type, and a CRC over the first 10. */
#ifndef KILOLIB_MESSAGE_H
#define KILOLIB_MESSAGE_H

#include <stdint.h>

typedef union {
    uint8_t rawdata[12];
    struct {
        uint8_t data[9];
        uint8_t type;
        uint16_t crc;
    };
} message_t;

/* Types from 0x80 are system messages, sent by the overhead controller. */
typedef enum {
    NORMAL = 0,
    GPS,
    SPECIAL = 0x80,
    BOOT = 0x80,
    BOOTPGM_PAGE,
    BOOTPGM_SIZE,
    RESET,
    SLEEP,
    WAKEUP,
    CHARGE,
    VOLTAGE,
    RUN,
    READUID,
    CALIB
} message_type_t;

#endif
