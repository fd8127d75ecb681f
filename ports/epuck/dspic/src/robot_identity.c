/* robot.h's robot_id and robot_console_init on the e-puck (dsPIC30F6014A).
 *
 * The dsPIC has no unique id, as the e-puck2's STM32 has: the robot's id
 * is the last word of its data EEPROM (0x7FFFFE), written once by whoever
 * numbers the robots (with the programmer, as the EEPROM is programmed, or
 * by an app); an erased word (0xFFFF) reads as 0, as an e-puck2 under QEMU
 * given no --id does.
 *
 * printf: XC16's C library sends its streams' bytes through write(), which
 * an app may define in place of the library's (the XC16 libraries guide);
 * this one sends standard output's and error's bytes to the console
 * (UART1, the Bluetooth link). */
#include "dspic_compiler.h"
#include "dspic_port.h"
#include "openswarm/robot.h"
#include "p30f6014a_registers.h"

/* The data EEPROM is program memory page 0x7F, 0x7FF000-0x7FFFFE on the
 * dsPIC30F6014A's 4 KB (DS70143, "Data EEPROM Memory"). */
#define EEPROM_PAGE 0x7Fu
#define ID_OFFSET 0xFFFEu
#define ERASED 0xFFFFu

uint16_t epuck_robot_id(void) {
    /* TBLPAG is shared with any code that reads program memory: put back
     * as it was, with nothing in between. */
    port_irq_state_t s = port_irq_save();
    uint16_t page = TBLPAG;
    TBLPAG = EEPROM_PAGE;
    uint16_t id = DSPIC_TABLE_READ_LOW(ID_OFFSET);
    TBLPAG = page;
    port_irq_restore(s);
    return id == ERASED ? 0u : id;
}

void epuck_console_init(void) { dspic_console_init(); }

/* Handles 1 and 2 (standard output and error) go to the console; there
 * are no files. */
int write(int handle, void *buffer, unsigned int len);
int write(int handle, void *buffer, unsigned int len) {
    if (handle != 1 && handle != 2) return -1;
    const char *bytes = buffer;
    for (unsigned int i = 0; i < len; i++) dspic_console_put(bytes[i]);
    return (int)len;
}
