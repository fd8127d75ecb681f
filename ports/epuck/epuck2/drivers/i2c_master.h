/* A small blocking I2C master on the e-puck2's I2C1 (SCL PB8, SDA PB9, the
 * bus of the camera, IMU and distance sensor), at 400 kHz. */
#ifndef EPUCK2_I2C_MASTER_H
#define EPUCK2_I2C_MASTER_H

#include <stdbool.h>
#include <stdint.h>

void epuck2_i2c_init(void);

/* START, address (7 bits) + write, reg, value, STOP. False if the device
 * did not acknowledge, the bus failed or the hardware did not answer in
 * time; the STOP is sent either way, so the bus is free again. */
bool epuck2_i2c_write(uint8_t address, uint8_t reg, uint8_t value);

#endif
