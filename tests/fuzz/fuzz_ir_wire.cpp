// Copyright (c) 2026 The OpenSwarm authors. MIT licence.
// The Kilobot's IR receiver, its wire-format half compiled for the host as
// the firmware has it (ports/kilobot/src/devices/ir_wire.h), fed with the
// pulse times a sender would make, as the firmware's interrupt feeds it
// (ir.c: receive_frame, next_edge, modelled below). Properties:
//  - a frame sent whole, at any start time, from a sender whose clock is up
//    to 2% off, with pulses up to 16 cycles early or late and the receiver
//    taking 16..100 cycles per pulse, is delivered exactly as it was sent;
//  - a frame whose CRC does not match is never delivered;
//  - a frame without its header's stop pulse is never delivered;
//  - any pulses at all: no frame is delivered without a header stop pulse,
//    and nothing reads or writes out of bounds (ASan, UBSan).
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include <fuzzer/FuzzedDataProvider.h>

extern "C" {
#include "ir_wire.h"
}

namespace {

constexpr int kMaxClockErrorPermille = 20;
constexpr int kMaxJitterCycles = 16;
constexpr int kMinLatencyCycles = 16, kMaxLatencyCycles = 100;

[[noreturn]] void fail(const char *what) {
    std::fprintf(stderr, "fuzz_ir_wire: %s\n", what);
    std::abort();
}

// How a frame is sent: the pulses' times in the receiver's cycles (64-bit:
// the receiver's 16-bit Timer1 sees them modulo 65536).
struct Sending {
    uint8_t frame[IR_WIRE_FRAME_BYTES];
    uint64_t start;
    int clock_error_permille; // the sender's slot is this much longer
    bool drop_header_stop;
};

bool pulse_in_slot(const uint8_t *frame, unsigned slot) {
    if (slot < IR_WIRE_HEADER_SLOTS) return slot == 0 || slot == IR_WIRE_HEADER_SLOTS - 1;
    unsigned s = slot - IR_WIRE_HEADER_SLOTS, bit = s % 10u;
    return bit == 0 || bit == 9 || ((frame[s / 10u] >> (bit - 1u)) & 1u);
}

std::vector<uint64_t> pulses_of(const Sending &s, FuzzedDataProvider &in) {
    std::vector<uint64_t> pulses;
    double slot_cycles = IR_WIRE_BIT * (1.0 + s.clock_error_permille / 1000.0);
    for (unsigned slot = 0; slot < IR_WIRE_SLOTS; slot++) {
        if (!pulse_in_slot(s.frame, slot)) continue;
        if (s.drop_header_stop && slot == IR_WIRE_HEADER_SLOTS - 1) continue;
        int jitter = slot == 0 ? 0 : in.ConsumeIntegralInRange(-kMaxJitterCycles, kMaxJitterCycles);
        pulses.push_back(s.start + (uint64_t)(slot * slot_cycles + kMaxJitterCycles + jitter));
    }
    return pulses;
}

// The firmware's reception of the pulses from the first on (its start):
// true if a frame was delivered (whole, CRC intact), into frame.
bool receive(const std::vector<uint64_t> &pulses, unsigned latency, uint8_t *frame) {
    ir_wire_decoder d;
    std::memset(frame, 0, IR_WIRE_FRAME_BYTES);
    ir_wire_decode_start(&d, (uint16_t)pulses[0], frame);
    uint64_t now = pulses[0] + latency;
    for (size_t next = 1;;) {
        // next_edge(d.last_pulse): Timer1's input capture keeps the latest
        // pulse; a poll first takes a captured one, else gives up once
        // Timer1 - d.last_pulse, in 16 bits, passes IR_WIRE_SILENCE.
        uint16_t waited = (uint16_t)((uint16_t)now - d.last_pulse);
        uint64_t give_up = waited > IR_WIRE_SILENCE ? now : now + (IR_WIRE_SILENCE + 1u - waited);
        if (next == pulses.size() || (pulses[next] > now && pulses[next] > give_up)) return false;
        while (next + 1 < pulses.size() && pulses[next + 1] <= now) next++; // overwritten captures
        uint64_t edge = pulses[next++];
        now = (edge > now ? edge : now) + latency;
        switch (ir_wire_decode_pulse(&d, (uint16_t)edge)) {
        case IR_WIRE_MORE:
        case IR_WIRE_HEADER_STOP: break;
        case IR_WIRE_WHOLE:
            if (!d.header_stopped) fail("a frame ended whole without its header's stop pulse");
            return ir_wire_frame_intact(frame);
        case IR_WIRE_COLLISION:
        case IR_WIRE_BROKEN: return false;
        }
    }
}

void check_crc() {
    static const uint8_t check[] = {'1', '2', '3', '4', '5', '6', '7', '8', '9'};
    if (ir_wire_crc(check, sizeof check) != 0x6F91) // CRC-16/MCRF4XX's check value
        fail("the host's CRC is not avr-libc's _crc_ccitt_update");
}

// A frame sent whole, or with its CRC or its header's stop pulse spoiled.
void sent_frame(FuzzedDataProvider &in) {
    Sending s{};
    in.ConsumeData(s.frame, IR_WIRE_CRC_BYTES);
    uint16_t crc = ir_wire_crc(s.frame, IR_WIRE_CRC_BYTES);
    uint16_t spoil = in.ConsumeBool() ? in.ConsumeIntegralInRange<uint16_t>(1, 0xFFFF) : 0;
    crc = (uint16_t)(crc ^ spoil);
    s.frame[10] = (uint8_t)crc;
    s.frame[11] = (uint8_t)(crc >> 8);
    s.start = in.ConsumeIntegral<uint16_t>();
    s.clock_error_permille = in.ConsumeIntegralInRange(-kMaxClockErrorPermille, kMaxClockErrorPermille);
    s.drop_header_stop = in.ConsumeBool();
    unsigned latency = in.ConsumeIntegralInRange(kMinLatencyCycles, kMaxLatencyCycles);
    std::vector<uint64_t> pulses = pulses_of(s, in);
    uint8_t got[IR_WIRE_FRAME_BYTES];
    bool delivered = receive(pulses, latency, got);
    if (s.drop_header_stop) {
        if (delivered) fail("a frame without its header's stop pulse was delivered");
    } else if (spoil != 0) {
        if (delivered) fail("a frame with a bad CRC was delivered");
    } else if (!delivered) {
        fail("a frame sent whole within the timing tolerances was lost");
    } else if (std::memcmp(got, s.frame, IR_WIRE_FRAME_BYTES) != 0) {
        fail("a delivered frame is not the one sent");
    }
}

// Any pulses: gaps of 1..3000 cycles.
void any_pulses(FuzzedDataProvider &in) {
    std::vector<uint64_t> pulses{in.ConsumeIntegral<uint16_t>()};
    while (in.remaining_bytes() > 1 && pulses.size() < 400)
        pulses.push_back(pulses.back() + in.ConsumeIntegralInRange(1, 3000));
    uint8_t got[IR_WIRE_FRAME_BYTES];
    receive(pulses, in.ConsumeIntegralInRange(kMinLatencyCycles, kMaxLatencyCycles), got);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    static bool crc_checked = (check_crc(), true);
    (void)crc_checked;
    FuzzedDataProvider in(data, size);
    if (in.ConsumeBool())
        sent_frame(in);
    else
        any_pulses(in);
    return 0;
}
