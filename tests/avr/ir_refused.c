/* A good frame the kernel has no room for is counted as refused, not as
 * received: robot uid 1 sends 20 frames, 25 ms apart; robot uid 2 holds a
 * critical section through them (events queue up, none is dispatched), so
 * its event queue fills. Both print their IR and kernel counters (checked
 * by avr.ir_refused). */
#include <avr/eeprom.h>

#include "openswarm/kernel.h"
#include "openswarm/kilobot.h"
#include "openswarm/kilobot_sim.h"

static uint16_t uid;
static uint8_t delivered;

static bool heard(sys_pid pid, sys_event_id e, const sys_event_data *d) {
    (void)pid;
    (void)e;
    (void)d;
    delivered++;
    return true;
}

static void print(const char *label, uint16_t value) {
    sim_puts_P(label);
    sim_put_uint(value);
}

static void talk(void *arg) {
    (void)arg;
    if (uid == 1) {
        Sys_Sleep(50);
        for (uint8_t seq = 0; seq < 20; seq++) {
            uint8_t msg[10] = {seq};
            Sys_Send_Event(KILOBOT_EVENT_IR_TX, msg, sizeof msg);
            Sys_Sleep(25);
        }
    } else {
        Sys_Start_CriticalSection();
        for (uint32_t until = Sys_Get_SystemTime() + 700; Sys_Get_SystemTime() < until;) {
        }
        Sys_End_CriticalSection();
    }
    Sys_Sleep(100);
    kilobot_ir_stats ir;
    kilobot_ir_get_stats(&ir);
    sys_stats k;
    Sys_Get_Stats(&k);
    print(PSTR("uid "), uid);
    print(PSTR(" sent "), ir.sent);
    print(PSTR(" received "), ir.received);
    print(PSTR(" refused "), ir.refused);
    print(PSTR(" delivered "), delivered);
    print(PSTR(" queue_full "), k.event_queue_full);
    sim_putc('\n');
    sim_exit(0);
}

int main(void) {
    uid = eeprom_read_word((const uint16_t *)KILOBOT_EEPROM_UID);
    Sys_Init_Kernel();
    if (kilobot_devices_init() != SYS_OK) sim_exit(2);
    Sys_Subscribe_to_Event(KILOBOT_EVENT_IR_RX, SYS_PID_SYSTEM, heard, NULL);
    Sys_Start_Process_Ex(talk, NULL, 96, 0, NULL);
    Sys_Start_Kernel();
    Sys_Run_SystemThread();
    return 0;
}
