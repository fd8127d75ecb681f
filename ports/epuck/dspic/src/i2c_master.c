/* The polled I2C master (i2c_master.h). Each step is started by a control
 * bit that the module clears when the step is over (SEN, RSEN, PEN, RCEN,
 * ACKEN) or, for a byte sent, by TRSTAT falling after the ninth clock,
 * when ACKSTAT holds the slave's answer. */
#include "i2c_master.h"

#include "p30f6014a_registers.h"

/* I2CBRG = Fcy / Fscl - Fcy / 1111111 - 1 (DS70046, I2C): 150 gives
 * 14745600 / (151 + 13.3) = 89.8 kHz, the e-puck library's setting, under
 * the sensor's 100 kHz. */
#define BRG 150u
/* A byte is 9 clocks of 11 us: a few hundred polls; 20000 is a bound for
 * a dead bus, not a timing. */
#define POLLS 20000u

static bool wait_clear(volatile uint16_t *reg, uint16_t bits) {
    for (uint16_t n = 0; n < POLLS; n++)
        if ((*reg & bits) == 0) return true;
    return false;
}

static bool step(uint16_t control_bit) {
    I2CCON |= control_bit;
    return wait_clear(&I2CCON, control_bit) && (I2CSTAT & I2CSTAT_BCL) == 0;
}

static bool send(uint8_t byte) {
    I2CTRN = byte;
    return wait_clear(&I2CSTAT, I2CSTAT_TRSTAT) && (I2CSTAT & (I2CSTAT_ACKSTAT | I2CSTAT_BCL)) == 0;
}

static bool receive(uint8_t *byte) {
    if (!step(I2CCON_RCEN)) return false;
    *byte = (uint8_t)I2CRCV;
    I2CCON |= I2CCON_ACKDT; /* one byte only: NACK it */
    return step(I2CCON_ACKEN);
}

static bool stop(bool ok) {
    return step(I2CCON_PEN) && ok;
}

void dspic_i2c_init(void) {
    I2CCON = 0;
    I2CBRG = BRG;
    I2CSTAT = 0;
    I2CCON = I2CCON_I2CEN; /* 7-bit addresses, slew rate control on */
}

bool dspic_i2c_write(uint8_t address, uint8_t reg, uint8_t value) {
    bool ok = step(I2CCON_SEN) && send((uint8_t)(address << 1)) && send(reg) && send(value);
    return stop(ok);
}

bool dspic_i2c_read(uint8_t address, uint8_t reg, uint8_t *value) {
    bool ok = step(I2CCON_SEN) && send((uint8_t)(address << 1)) && send(reg) && step(I2CCON_RSEN) &&
              send((uint8_t)(address << 1 | 1u)) && receive(value);
    return stop(ok);
}
