/* The EEPROM in the native mode: the robot's own 1 KB, which the
 * simulator fills as it does a robot's in the exact mode (calibration,
 * distance tables, uid). A write costs the robot the 3.4 ms it takes. */
#ifndef OPENSWARM_NATIVE_AVR_EEPROM_H
#define OPENSWARM_NATIVE_AVR_EEPROM_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* An address in the EEPROM: variables there are the program's own RAM in
 * the native mode, so EEMEM is left out (their addresses mean nothing). */
#define EEMEM

uint8_t eeprom_read_byte(const uint8_t *address);
uint16_t eeprom_read_word(const uint16_t *address);
uint32_t eeprom_read_dword(const uint32_t *address);
void eeprom_read_block(void *to, const void *address, size_t n);
void eeprom_write_byte(uint8_t *address, uint8_t value);
void eeprom_write_word(uint16_t *address, uint16_t value);
void eeprom_write_dword(uint32_t *address, uint32_t value);
void eeprom_write_block(const void *from, void *address, size_t n);
void eeprom_update_byte(uint8_t *address, uint8_t value);
void eeprom_update_word(uint16_t *address, uint16_t value);
void eeprom_update_dword(uint32_t *address, uint32_t value);
void eeprom_update_block(const void *from, void *address, size_t n);
#define eeprom_busy_wait() ((void)0)
#define eeprom_is_ready() 1

#ifdef __cplusplus
}
#endif

#endif
