/* The EEPROM in the native mode (avr/eeprom.h): the robot's 1 KB in its
 * native_io, addresses taken modulo its size as the chip's address
 * register does. A byte written costs the 3.4 ms the chip takes, while
 * interrupts come as they are due. */
#include "native_internal.h"

#include <avr/eeprom.h>

#define WRITE_CYCLES 27200u /* 3.4 ms at 8 MHz */
#define SIZE NATIVE_EEPROM_BYTES

static uint8_t *cell(const void *address) {
    return &native_io_of_robot->eeprom[(uintptr_t)address % SIZE];
}

void eeprom_read_block(void *to, const void *address, size_t n) {
    native_spend(4u * n);
    for (size_t i = 0; i < n; i++) ((uint8_t *)to)[i] = *cell((const uint8_t *)address + i);
}

uint8_t eeprom_read_byte(const uint8_t *address) {
    uint8_t v;
    eeprom_read_block(&v, address, 1);
    return v;
}

/* Little-endian, as avr-libc lays a word out. */
uint16_t eeprom_read_word(const uint16_t *address) {
    uint8_t b[2];
    eeprom_read_block(b, address, 2);
    return (uint16_t)(b[0] | b[1] << 8);
}

uint32_t eeprom_read_dword(const uint32_t *address) {
    uint8_t b[4];
    eeprom_read_block(b, address, 4);
    return (uint32_t)b[0] | (uint32_t)b[1] << 8 | (uint32_t)b[2] << 16 | (uint32_t)b[3] << 24;
}

static void write_bytes(const uint8_t *from, void *address, size_t n, int only_changed) {
    for (size_t i = 0; i < n; i++) {
        uint8_t *c = cell((uint8_t *)address + i);
        if (only_changed && *c == from[i]) continue;
        native_wait_for_hardware(WRITE_CYCLES);
        *c = from[i];
    }
}

void eeprom_write_block(const void *from, void *address, size_t n) { write_bytes(from, address, n, 0); }
void eeprom_update_block(const void *from, void *address, size_t n) { write_bytes(from, address, n, 1); }

void eeprom_write_byte(uint8_t *address, uint8_t value) { write_bytes(&value, address, 1, 0); }
void eeprom_update_byte(uint8_t *address, uint8_t value) { write_bytes(&value, address, 1, 1); }

void eeprom_write_word(uint16_t *address, uint16_t value) {
    uint8_t b[2] = {(uint8_t)value, (uint8_t)(value >> 8)};
    write_bytes(b, address, 2, 0);
}

void eeprom_update_word(uint16_t *address, uint16_t value) {
    uint8_t b[2] = {(uint8_t)value, (uint8_t)(value >> 8)};
    write_bytes(b, address, 2, 1);
}

void eeprom_write_dword(uint32_t *address, uint32_t value) {
    uint8_t b[4] = {(uint8_t)value, (uint8_t)(value >> 8), (uint8_t)(value >> 16), (uint8_t)(value >> 24)};
    write_bytes(b, address, 4, 0);
}

void eeprom_update_dword(uint32_t *address, uint32_t value) {
    uint8_t b[4] = {(uint8_t)value, (uint8_t)(value >> 8), (uint8_t)(value >> 16), (uint8_t)(value >> 24)};
    write_bytes(b, address, 4, 1);
}
