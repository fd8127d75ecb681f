/* Program memory in the native mode: constants live where the host keeps
 * them, and reading them is reading them. */
#ifndef OPENSWARM_NATIVE_AVR_PGMSPACE_H
#define OPENSWARM_NATIVE_AVR_PGMSPACE_H

#include <stdint.h>
#include <stdio.h>
#include <string.h>

#define PROGMEM
#define PGM_P const char *
#define PSTR(s) (s)
#define pgm_read_byte(p) (*(const uint8_t *)(p))
#define pgm_read_word(p) (*(const uint16_t *)(p))
#define pgm_read_dword(p) (*(const uint32_t *)(p))
#define pgm_read_ptr(p) (*(void *const *)(p))
#define memcpy_P memcpy
#define strcpy_P strcpy
#define strncpy_P strncpy
#define strcmp_P strcmp
#define strlen_P strlen
#define printf_P printf
#define sprintf_P sprintf
#define snprintf_P snprintf
#define puts_P puts

#endif
