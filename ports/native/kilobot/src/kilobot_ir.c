/* The Kilobot's IR at message level: a frame goes out whole (the
 * simulator hands it to the robots in range), and arrives whole, with the
 * two gain readings its header gave. The timing is the wire's: a
 * transmission keeps interrupts masked for the frame's 4.4 ms, a reception
 * from its first pulse to its last; the receiver's interrupt comes at the
 * first pulse, and a frame whose first pulse found interrupts masked for
 * longer than a slot is lost, as the input capture loses it. Frames reach
 * their receivers a window late (sim/src/native/native_air.h); carrier
 * sense sees them at once. What the
 * frame does next is the HAL device's (ports/kilobot/src/devices/ir_device.c). */
#include "native_internal.h"

#include <string.h>

#include "devices/devices_internal.h"
#include "devices/ir_wire.h"
#include "openswarm/kilobot.h"

#define FRAME_CYCLES ((uint64_t)IR_WIRE_SLOTS * IR_WIRE_BIT)

void kilobot_ir_start(void) {}

/* Carrier sense is the simulator's: it knows when every robot in range
 * began its frames, up to this moment, even in the window under way (the
 * robot yields until it has looked). A frame this robot is receiving is
 * one of them. */
sys_status kilobot_ir_transmit(const uint8_t frame[KILOBOT_IR_FRAME_BYTES]) {
    port_irq_state_t s = port_irq_save();
    native_io *io = native_io_of_robot;
    native_make_room(&io->n_sent, NATIVE_SENT_ROOM);
    native_sent *out = &io->sent[io->n_sent++];
    out->at = native_now;
    memcpy(out->bytes, frame, NATIVE_FRAME_BYTES);
    io->transmit = NATIVE_TRANSMIT_ASKED;
    native_yield();
    int clear = io->transmit == NATIVE_TRANSMIT_CLEAR;
    io->transmit = NATIVE_TRANSMIT_NONE;
    if (!clear) {
        kilobot_ir_count(&kilobot_ir_counters.busy);
        port_irq_restore(s);
        return SYS_E_QUEUE_FULL;
    }
    native_spend(FRAME_CYCLES); /* its slots, interrupts masked */
    kilobot_ir_count(&kilobot_ir_counters.sent);
    port_irq_restore(s); /* the ticks the frame held back come now */
    return SYS_OK;
}

uint32_t native_ir_receptions;

/* The receiver polls for a frame's pulses in a loop of about 30 cycles
 * (ir.c's next_edge, with take_missed_tick: avr-objdump of
 * world_distances.elf), so it sees the last one up to a loop later. */
#define EDGE_POLL_CYCLES 32u

/* The receiver's interrupt, at the inbox's first frame's first pulse (or
 * later, if interrupts were masked then). */
void native_ir_interrupt(void) {
    native_io *io = native_io_of_robot;
    int late = native_now - io->inbox[io->inbox_head].start > IR_WIRE_BIT;
    native_ir_receptions++;
    /* Its slots, interrupts masked. Where in its polling loop a robot sees
     * the last pulse is not simulated: drawn instead. Robots that heard one
     * frame would otherwise all leave its end on the same cycle and all
     * send at once; drawn within a whole slot instead, they fell apart
     * further than in the exact mode, whose receivers leave within a few
     * tens of cycles of each other (--ir-log: neighbours that start
     * together after a frame start 0-40 cycles apart), and the native
     * robots collided half as often. */
    uint64_t end = io->inbox[io->inbox_head].end + native_random() % EDGE_POLL_CYCLES;
    if (end > native_now) native_spend(end - native_now);
    /* The simulator may have found it collided meanwhile: read it now. */
    const native_frame *f = &io->inbox[io->inbox_head];
    kilobot_ir_rx rx;
    memset(&rx, 0, sizeof rx);
    memcpy(rx.frame, f->bytes, sizeof rx.frame);
    rx.low_gain = f->low_gain;
    rx.high_gain = f->high_gain;
    int damage = f->damage;
    io->inbox_head = (io->inbox_head + 1u) % NATIVE_INBOX_ROOM;
    io->inbox_count--;
    if (damage == NATIVE_FRAME_COLLIDED)
        kilobot_ir_count(&kilobot_ir_counters.collisions);
    else if (damage == NATIVE_FRAME_BROKEN || late)
        kilobot_ir_count(&kilobot_ir_counters.broken);
    else
        kilobot_ir_deliver(&rx);
}
