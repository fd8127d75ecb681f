/* The IR device for the HAL: its Rx processor checks a frame's CRC, its
 * Tx processor adds it, and its counters. The board's lower layer moves
 * the frames: ir.c on the Kilobot (the wire), ports/native at message
 * level in the native mode. */
#include "openswarm/kilobot.h"
#include "openswarm/port.h"

#include <string.h>

#include "devices_internal.h"
#include "ir_wire.h"

/* The simulator reads it from the firmware's RAM by name (openswarm-sim
 * --counters). */
kilobot_ir_stats kilobot_ir_counters;

void kilobot_ir_count(uint16_t *counter) {
    if (*counter != UINT16_MAX) (*counter)++;
}

uint16_t kilobot_crc(const uint8_t *bytes, uint8_t n) {
    return ir_wire_crc(bytes, n);
}

void kilobot_ir_get_stats(kilobot_ir_stats *out) {
    port_irq_state_t s = port_irq_save();
    *out = kilobot_ir_counters;
    port_irq_restore(s);
}

/* In the receiver's interrupt: the Rx processor checks the CRC; a good
 * frame may still find the kernel full. */
void kilobot_ir_deliver(const kilobot_ir_rx *rx) {
    os_isr_enter();
    sys_status st = Sys_Device_Read(&kilobot_ir, rx, sizeof *rx, NULL, 0, NULL);
    if (st == SYS_OK)
        kilobot_ir_count(&kilobot_ir_counters.received);
    else if (st != SYS_E_NOT_FOUND)
        kilobot_ir_count(&kilobot_ir_counters.refused);
    os_isr_exit();
}

/* ---- the HAL comm device ---- */

/* Rx: a frame whose CRC checks becomes a KILOBOT_EVENT_IR_RX, unless it
 * is a system message the overhead control takes. */
uint8_t kilobot_ir_check_crc(sys_device *dev, const void *in, uint8_t size, void *out, uint8_t cap) {
    (void)dev;
    const kilobot_ir_rx *r = in;
    if (size != sizeof *r || cap < sizeof *r) return 0;
    if (!ir_wire_frame_intact(r->frame)) {
        kilobot_ir_count(&kilobot_ir_counters.bad_crc);
        return 0;
    }
    if (kilobot_overhead_control_take(r->frame)) return 0; /* the robot's, not the app's */
    memcpy(out, r, sizeof *r);
    return sizeof *r;
}

/* Tx: 10 bytes (data + type) get their CRC. */
static uint8_t add_crc(sys_device *dev, const void *in, uint8_t size, void *out, uint8_t cap) {
    (void)dev;
    if (size != 10u || cap < KILOBOT_IR_FRAME_BYTES) return 0;
    uint8_t *f = out;
    memcpy(f, in, 10);
    uint16_t crc = kilobot_crc(f, 10);
    f[10] = (uint8_t)crc;
    f[11] = (uint8_t)(crc >> 8);
    return KILOBOT_IR_FRAME_BYTES;
}

static void ir_write(sys_device *dev, const void *raw, uint8_t size) {
    (void)dev;
    if (size == KILOBOT_IR_FRAME_BYTES) kilobot_ir_transmit(raw);
}

sys_device kilobot_ir = {"ir", SYS_DEVICE_COMM, KILOBOT_EVENT_IR_RX, KILOBOT_EVENT_IR_TX,
                         kilobot_ir_check_crc, add_crc, ir_write, NULL, 0};
