/* Two raw frames on the air, for openswarm-sim --ir-log: one with its CRC,
 * one with the CRC's last bit flipped. The simulator decodes both from the
 * flashes by the wire format alone (checked by ctest). */
#include "openswarm/kernel.h"
#include "openswarm/kilobot.h"
#include "openswarm/kilobot_sim.h"

static void send(uint8_t first, uint8_t crc_flip) {
    uint8_t frame[KILOBOT_IR_FRAME_BYTES] = {first, 0x5A, 0xFF, 0, 0, 0, 0, 0, 0x80, 0x01};
    uint16_t crc = (uint16_t)(kilobot_crc(frame, 10) ^ crc_flip);
    frame[10] = (uint8_t)crc;
    frame[11] = (uint8_t)(crc >> 8);
    while (kilobot_ir_transmit(frame) != SYS_OK) Sys_Sleep(1);
}

static void talk(void) {
    Sys_Sleep(10);
    send(0xA1, 0);
    Sys_Sleep(10);
    send(0xA2, 1);
    Sys_Sleep(10);
    sim_exit(0);
}

int main(void) {
    Sys_Init_Kernel();
    kilobot_devices_init();
    Sys_Start_Process(talk);
    Sys_Start_Kernel();
    Sys_Run_SystemThread();
    return 0;
}
