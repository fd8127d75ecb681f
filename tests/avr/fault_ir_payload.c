/* No corrupted message is delivered, and every frame is counted once,
 * under IR faults (openswarm-sim --faults flip=...,cut=...): robot uid 1
 * sends FRAMES frames, each with its sequence number and a payload that
 * follows from it; every other robot checks each frame delivered to it
 * against that pattern and, at the end, prints its IR counters, the
 * frames delivered and the corrupt ones among them (checked by
 * tests/avr/check_fault_ir.py, avr.fault_ir_payload). */
#include <avr/eeprom.h>

#include "openswarm/kernel.h"
#include "openswarm/kilobot.h"
#include "openswarm/kilobot_sim.h"

#define FRAMES 150
#define PERIOD_MS 20
#define TYPE 0x42
#define SEND_MS 5 /* a frame takes 4.4 ms */
#define REPORT_AT_MS (100u + FRAMES * (PERIOD_MS + SEND_MS) + 300u)

static uint16_t uid;
static uint16_t delivered, corrupt, out_of_order;
static int16_t last_seq = -1;

/* Byte i (1..8) of frame seq's payload. */
static uint8_t pattern(uint8_t seq, uint8_t i) { return (uint8_t)((seq * 37u + i * 101u) ^ 0xA5u); }

static bool heard(sys_pid pid, sys_event_id e, const sys_event_data *d) {
    (void)pid;
    (void)e;
    const kilobot_ir_rx *rx = d->value;
    bool good = rx->frame[9] == TYPE;
    for (uint8_t i = 1; i < 9; i++) good = good && rx->frame[i] == pattern(rx->frame[0], i);
    delivered++;
    if (!good) corrupt++;
    if ((int16_t)rx->frame[0] <= last_seq) out_of_order++;
    last_seq = rx->frame[0];
    return true;
}

static void print(const char *label, uint16_t value) {
    sim_puts_P(label);
    sim_put_uint(value);
}

static void report(void) {
    kilobot_ir_stats ir;
    kilobot_ir_get_stats(&ir);
    print(PSTR("uid "), uid);
    print(PSTR(" sent "), ir.sent);
    print(PSTR(" received "), ir.received);
    print(PSTR(" refused "), ir.refused);
    print(PSTR(" bad_crc "), ir.bad_crc);
    print(PSTR(" broken "), ir.broken);
    print(PSTR(" collisions "), ir.collisions);
    print(PSTR(" busy "), ir.busy);
    print(PSTR(" delivered "), delivered);
    print(PSTR(" corrupt "), corrupt);
    print(PSTR(" out_of_order "), out_of_order);
    sim_putc('\n');
}

static void talk(void *arg) {
    (void)arg;
    Sys_Sleep(100);
    for (uint8_t seq = 0; seq < FRAMES && uid == 1; seq++) {
        uint8_t msg[10] = {seq};
        for (uint8_t i = 1; i < 9; i++) msg[i] = pattern(seq, i);
        msg[9] = TYPE;
        Sys_Send_Event(KILOBOT_EVENT_IR_TX, msg, sizeof msg);
        Sys_Sleep(PERIOD_MS);
    }
    while (Sys_Get_SystemTime() < REPORT_AT_MS) Sys_Sleep(10);
    report();
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
