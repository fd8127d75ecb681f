/* The dsPIC's I2C module as a small polled master (SCL RG2, SDA RG3: the
 * e-puck's camera bus), about 90 kHz. Every wait is bounded: a bus that
 * does not answer fails the call instead of hanging the robot. */
#ifndef DSPIC_I2C_MASTER_H
#define DSPIC_I2C_MASTER_H

#include <stdbool.h>
#include <stdint.h>

void dspic_i2c_init(void);

/* START, address (7 bits) + write, reg, value, STOP. False on a NACK, a
 * collision or a timeout; the STOP is sent either way. */
bool dspic_i2c_write(uint8_t address, uint8_t reg, uint8_t value);

/* START, address + write, reg, repeated START, address + read, one byte
 * answered with NACK, STOP. */
bool dspic_i2c_read(uint8_t address, uint8_t reg, uint8_t *value);

#endif
