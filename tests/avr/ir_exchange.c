/* Two robots on the simulator's IR channel: robot uid 1 sends a frame every
 * 100 ms through the IR device's Tx processor; every robot prints what its
 * Rx processor (the distance pre-processor) accepts (checked by ctest). */
#include <avr/eeprom.h>
#include <string.h>

#include "openswarm/kernel.h"
#include "openswarm/kilobot.h"
#include "openswarm/kilobot_sim.h"

static uint16_t uid;

static bool heard(sys_pid pid, sys_event_id e, const sys_event_data *d) {
    (void)pid;
    (void)e;
    const kilobot_ir_rx *rx = d->value;
    sim_puts_P(PSTR("uid "));
    sim_put_uint(uid);
    sim_puts_P(PSTR(" heard uid "));
    sim_put_uint((uint16_t)(rx->frame[0] | rx->frame[1] << 8));
    sim_puts_P(PSTR(" seq "));
    sim_put_uint(rx->frame[2]);
    sim_puts_P(PSTR(" gains "));
    sim_put_uint((uint16_t)rx->high_gain);
    sim_putc('/');
    sim_put_uint((uint16_t)rx->low_gain);
    sim_puts_P(PSTR(" mm "));
    sim_put_uint(rx->distance_mm);
    sim_putc('\n');
    return true;
}

static void talk(void *arg) {
    (void)arg;
    for (uint8_t seq = 1; seq <= 3; seq++) {
        Sys_Sleep(100);
        if (uid != 1) continue;
        uint8_t msg[10] = {(uint8_t)uid, (uint8_t)(uid >> 8), seq};
        Sys_Send_Event(KILOBOT_EVENT_IR_TX, msg, sizeof msg);
    }
    Sys_Sleep(20);
    kilobot_ir_stats s;
    kilobot_ir_get_stats(&s);
    sim_puts_P(PSTR("uid "));
    sim_put_uint(uid);
    sim_puts_P(PSTR(" sent "));
    sim_put_uint(s.sent);
    sim_puts_P(PSTR(" received "));
    sim_put_uint(s.received);
    sim_puts_P(PSTR(" bad "));
    sim_put_uint(s.bad_crc);
    sim_putc('\n');
    sim_exit(0);
}

int main(void) {
    uid = eeprom_read_word((const uint16_t *)KILOBOT_EEPROM_UID);
    Sys_Init_Kernel();
    if (kilobot_devices_init() != SYS_OK) sim_exit(2);
    Sys_Set_Processor(&kilobot_ir, kilobot_ir_with_distance, NULL);
    Sys_Subscribe_to_Event(KILOBOT_EVENT_IR_RX, SYS_PID_SYSTEM, heard, NULL);
    Sys_Start_Process_Ex(talk, NULL, 96, 0, NULL);
    Sys_Start_Kernel();
    Sys_Run_SystemThread();
    return 0;
}
