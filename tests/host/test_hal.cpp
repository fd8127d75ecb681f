// The HAL: input, output and communication devices, their replaceable
// processors, virtual sensors and safety measures (paper, section III.C).
#include "kernel_fixture.hpp"

#include <cstdio>
#include <cstring>

using Hal = KernelTest;

static_assert(OS_CFG_MAX_DEVICES == 4, "the table-full test assumes the test config");

namespace {

template <typename T> T load(const void *p) {
    T v;
    std::memcpy(&v, p, sizeof v);
    return v;
}

template <typename T> uint8_t store(void *out, uint8_t capacity, T v) {
    if (capacity < sizeof v) return 0;
    std::memcpy(out, &v, sizeof v);
    return sizeof v;
}

sys_device make_device(const char *name, sys_device_kind kind, sys_event_id event,
                       sys_processor processor, void *params) {
    sys_device d{};
    d.name = name;
    d.kind = kind;
    d.event = event;
    d.processor = processor;
    d.params = params;
    return d;
}

std::string hex(const void *bytes, uint8_t size) {
    std::string s;
    for (uint8_t i = 0; i < size; i++) {
        char b[4];
        std::snprintf(b, sizeof b, "%s%02x", i ? " " : "", static_cast<const uint8_t *>(bytes)[i]);
        s += b;
    }
    return s;
}

// Handler: notes every int16 occurrence (or its wrong size).
bool note_int16(sys_pid, sys_event_id, const sys_event_data *d) {
    note(d->size == 2 ? std::to_string(load<int16_t>(d->value)) : "size" + std::to_string(d->size));
    return true;
}

// Lower layer of a motor: notes the raw int16 it would apply.
void motor_write(sys_device *dev, const void *raw, uint8_t size) {
    note(std::string(dev->name) + "=" + (size == 2 ? std::to_string(load<int16_t>(raw)) : "?"));
}

// ---- an IR proximity sensor: non-linear ADC counts -> millimetres ----

struct Point {
    uint16_t adc;
    int16_t mm;
};
struct Table {
    const Point *points; // by falling ADC value
    size_t n;
};
const Point bare[] = {{4000, 0}, {3520, 5}, {2000, 20}, {1000, 40}, {200, 100}};
const Point covered[] = {{4000, 10}, {3520, 15}, {2000, 30}, {1000, 50}, {200, 110}};
Table bare_table{bare, 5};
Table covered_table{covered, 5};

// Interpolates in dev->params (a Table); outside the table there is no reading.
uint8_t linearise(sys_device *dev, const void *in, uint8_t size, void *out, uint8_t capacity) {
    if (size != sizeof(uint16_t)) return 0;
    const Table *t = static_cast<const Table *>(dev->params);
    int adc = load<uint16_t>(in);
    for (size_t i = 0; i + 1 < t->n; i++) {
        const Point &hi = t->points[i], &lo = t->points[i + 1];
        if (adc <= hi.adc && adc >= lo.adc) {
            int mm = hi.mm + (hi.adc - adc) * (lo.mm - hi.mm) / (hi.adc - lo.adc);
            return store(out, capacity, static_cast<int16_t>(mm));
        }
    }
    return 0;
}

} // namespace

TEST_F(Hal, PreProcessorLinearisesRawAdcReadings) {
    sys_device prox = make_device("prox", SYS_DEVICE_INPUT, EV_A, linearise, &bare_table);
    boot([&] {
        EXPECT_STATUS(SYS_OK, Sys_Register_Device(&prox));
        EXPECT_STATUS(SYS_OK, Sys_Subscribe_to_Event(EV_A, SYS_PID_SYSTEM, note_int16, nullptr));
        spawn([&] {
            for (uint16_t raw : {4000, 3520, 2000, 1500, 600}) {
                EXPECT_STATUS(SYS_OK, Sys_Device_Input(&prox, &raw, sizeof raw));
            }
        });
    });
    settle();
    EXPECT_EQ("0 5 20 30 70", joined()) << "the paper's example: ADC 3520 is 5 mm";
    EXPECT_EQ(0, prox.rejected);
}

TEST_F(Hal, ReplacingTheProcessorAtRunTimeChangesTheEmittedValues) {
    sys_device prox = make_device("prox", SYS_DEVICE_INPUT, EV_A, linearise, &bare_table);
    boot([&] {
        Sys_Register_Device(&prox);
        Sys_Subscribe_to_Event(EV_A, SYS_PID_SYSTEM, note_int16, nullptr);
        spawn([&] {
            uint16_t raw = 3520;
            Sys_Device_Input(&prox, &raw, sizeof raw);
            EXPECT_STATUS(SYS_OK, Sys_Set_Processor(&prox, linearise, &covered_table));
            Sys_Device_Input(&prox, &raw, sizeof raw);
            EXPECT_STATUS(SYS_OK, Sys_Set_Processor(&prox, nullptr, nullptr)); // plain copy
            Sys_Device_Input(&prox, &raw, sizeof raw);
            EXPECT_STATUS(SYS_E_INVALID, Sys_Set_Processor(nullptr, linearise, nullptr));
        });
    });
    settle();
    EXPECT_EQ("5 15 3520", joined());
    EXPECT_EQ(nullptr, prox.processor);
    EXPECT_EQ(nullptr, prox.params);
}

TEST_F(Hal, PreProcessorReturningZeroEmitsNothingAndIsCounted) {
    sys_device prox = make_device("prox", SYS_DEVICE_INPUT, EV_A, linearise, &bare_table);
    sys_status kept_before = SYS_OK;
    boot([&] {
        Sys_Register_Device(&prox);
        Sys_Subscribe_to_Event(EV_A, SYS_PID_SYSTEM, note_int16, nullptr);
        spawn([&] {
            uint16_t saturated = 4095, too_far = 100, wrong_size = 3520;
            EXPECT_STATUS(SYS_OK, Sys_Device_Input(&prox, &saturated, sizeof saturated));
            EXPECT_STATUS(SYS_OK, Sys_Device_Input(&prox, &too_far, sizeof too_far));
            EXPECT_STATUS(SYS_OK, Sys_Device_Input(&prox, &wrong_size, 1));
            kept_before = Sys_Get_EventData(EV_A, nullptr, 0, nullptr);
            uint16_t good = 2000;
            Sys_Device_Input(&prox, &good, sizeof good);
        });
    });
    settle();
    EXPECT_EQ("20", joined());
    EXPECT_EQ(3, prox.rejected);
    EXPECT_STATUS(SYS_E_NOT_FOUND, kept_before) << "a rejected reading must not become event data";
}

TEST_F(Hal, ValuesLargerThanTheHalLimitAreRejected) {
    // A processor that claims more bytes than it may write, and a raw value
    // too large to copy when there is no processor.
    sys_device liar = make_device(
        "liar", SYS_DEVICE_INPUT, EV_A,
        [](sys_device *, const void *, uint8_t, void *, uint8_t capacity) -> uint8_t {
            return static_cast<uint8_t>(capacity + 1);
        },
        nullptr);
    sys_device copier = make_device("copier", SYS_DEVICE_INPUT, EV_B, nullptr, nullptr);
    boot([&] {
        Sys_Register_Device(&liar);
        Sys_Register_Device(&copier);
        Sys_Subscribe_to_Event(EV_A, SYS_PID_SYSTEM, note_int16, nullptr);
        Sys_Subscribe_to_Event(EV_B, SYS_PID_SYSTEM, note_int16, nullptr);
        spawn([&] {
            uint8_t big[OS_CFG_HAL_MAX_VALUE + 1] = {};
            int16_t small = 42;
            Sys_Device_Input(&liar, &small, sizeof small);
            Sys_Device_Input(&copier, big, sizeof big);
            Sys_Device_Input(&copier, &small, sizeof small);
        });
    });
    settle();
    EXPECT_EQ("42", joined());
    EXPECT_EQ(1, liar.rejected);
    EXPECT_EQ(1, copier.rejected);
}

namespace {
sys_pid handler_pid = SYS_PID_NONE;
sys_pid handler_ran_in = SYS_PID_NONE;
} // namespace

TEST_F(Hal, InputFromAnInterruptReachesSubscribedHandlersAndWaiters) {
    handler_pid = handler_ran_in = SYS_PID_NONE;
    sys_device prox = make_device("prox", SYS_DEVICE_INPUT, EV_A, linearise, &bare_table);
    sys_pid reader = SYS_PID_NONE;
    int16_t waited = 0;
    sys_status wait_status = SYS_E_INVALID;
    boot([&] {
        Sys_Register_Device(&prox);
        reader = spawn([&] {
            auto handler = [](sys_pid pid, sys_event_id, const sys_event_data *d) -> bool {
                handler_pid = pid;
                handler_ran_in = Sys_Get_ProcessID();
                note("handler:" + std::to_string(load<int16_t>(d->value)));
                return true;
            };
            EXPECT_STATUS(SYS_OK,
                          Sys_Subscribe_to_Event(EV_A, Sys_Get_ProcessID(), handler, nullptr));
            wait_status = Sys_Wait_for_Event(EV_A, &waited, sizeof waited, nullptr);
            note("woke");
        });
    });
    settle();
    ASSERT_EQ(SYS_PROCESS_BLOCKED, state_of(reader));
    EXPECT_EQ("", joined());

    sys_status st = SYS_E_INVALID;
    irq([&] {
        uint16_t raw = 2000;
        st = Sys_Device_Input(&prox, &raw, sizeof raw);
    });
    settle();
    EXPECT_STATUS(SYS_OK, st);
    EXPECT_EQ("handler:20 woke", joined());
    EXPECT_STATUS(SYS_OK, wait_status);
    EXPECT_EQ(20, waited);
    EXPECT_EQ(reader, handler_pid) << "the handler is told which thread subscribed it";
    EXPECT_EQ(SYS_PID_SYSTEM, handler_ran_in) << "handlers run in the system thread";
}

namespace {
// Post-processor of a motor: mm/s -> wheel steps/s (e-puck: 1000 steps/s
// is 129 mm/s), the ratio in dev->params.
struct Ratio {
    int num, den;
};
uint8_t speed_to_steps(sys_device *dev, const void *in, uint8_t size, void *out,
                       uint8_t capacity) {
    if (size != sizeof(int16_t)) return 0;
    const Ratio *r = static_cast<const Ratio *>(dev->params);
    return store(out, capacity, static_cast<int16_t>(load<int16_t>(in) * r->num / r->den));
}
} // namespace

TEST_F(Hal, OutputPostProcessorConvertsACommandForTheLowerLayer) {
    Ratio epuck{1000, 129};
    sys_device motor = make_device("left", SYS_DEVICE_OUTPUT, EV_B, speed_to_steps, &epuck);
    motor.write = motor_write;
    boot([&] {
        EXPECT_STATUS(SYS_OK, Sys_Register_Device(&motor));
        spawn([&] {
            for (int16_t speed : {129, -258, 0}) {
                EXPECT_STATUS(SYS_OK, Sys_Send_IntEvent(EV_B, speed));
                note("sent");
            }
            int16_t raw = 1;
            EXPECT_STATUS(SYS_E_INVALID, Sys_Device_Input(&motor, &raw, sizeof raw))
                << "an output device takes no input";
        });
    });
    settle();
    EXPECT_EQ("left=1000 sent left=-2000 sent left=0 sent", joined());
    EXPECT_EQ(0, motor.rejected);
}

namespace {
// A safety measure in the post-processor: while an unsafe area is ahead,
// forward speed is capped; backing away stays allowed.
struct Safety {
    bool unsafe_ahead;
    int16_t forward_cap;
};
uint8_t safe_speed(sys_device *dev, const void *in, uint8_t size, void *out, uint8_t capacity) {
    if (size != sizeof(int16_t)) return 0;
    const Safety *s = static_cast<const Safety *>(dev->params);
    int16_t speed = load<int16_t>(in);
    if (s->unsafe_ahead && speed > s->forward_cap) speed = s->forward_cap;
    return store(out, capacity, speed);
}
sys_device *guarded_motor = nullptr;
bool on_unsafe_area(sys_pid, sys_event_id, const sys_event_data *d) {
    static_cast<Safety *>(guarded_motor->params)->unsafe_ahead = load<int16_t>(d->value) != 0;
    return true;
}
} // namespace

TEST_F(Hal, SafetyPostProcessorOverridesAnUnsafeCommand) {
    Safety safety{false, 50};
    sys_device motor = make_device("motor", SYS_DEVICE_OUTPUT, EV_B, safe_speed, &safety);
    motor.write = motor_write;
    guarded_motor = &motor;
    boot([&] {
        Sys_Register_Device(&motor);
        Sys_Register_Event(EV_C); // "unsafe area ahead", e.g. from a floor sensor
        Sys_Subscribe_to_Event(EV_C, SYS_PID_SYSTEM, on_unsafe_area, nullptr);
        spawn([&] {
            Sys_Send_IntEvent(EV_B, 200);
            Sys_Send_IntEvent(EV_C, 1);
            Sys_Send_IntEvent(EV_B, 200);
            Sys_Send_IntEvent(EV_B, -200);
            Sys_Send_IntEvent(EV_B, 30);
            Sys_Send_IntEvent(EV_C, 0);
            Sys_Send_IntEvent(EV_B, 200);
        });
    });
    settle();
    EXPECT_EQ("motor=200 motor=50 motor=-200 motor=30 motor=200", joined());
    EXPECT_FALSE(safety.unsafe_ahead);
}

namespace {
// A serial protocol: 0x7E, length, payload, checksum (all bytes after the
// start byte sum to 0 modulo 256).
constexpr uint8_t START = 0x7E;

uint8_t frame_tx(sys_device *, const void *in, uint8_t size, void *out, uint8_t capacity) {
    if (size == 0 || size + 3 > capacity) return 0;
    uint8_t *f = static_cast<uint8_t *>(out);
    f[0] = START;
    f[1] = size;
    std::memcpy(f + 2, in, size);
    uint8_t sum = 0;
    for (uint8_t i = 1; i < size + 2; i++) sum = static_cast<uint8_t>(sum + f[i]);
    f[size + 2] = static_cast<uint8_t>(-sum);
    return static_cast<uint8_t>(size + 3);
}

uint8_t frame_rx(sys_device *, const void *in, uint8_t size, void *out, uint8_t capacity) {
    const uint8_t *f = static_cast<const uint8_t *>(in);
    if (size < 4 || f[0] != START || f[1] != size - 3 || f[1] > capacity) return 0;
    uint8_t sum = 0;
    for (uint8_t i = 1; i < size; i++) sum = static_cast<uint8_t>(sum + f[i]);
    if (sum != 0) return 0;
    std::memcpy(out, f + 2, f[1]);
    return f[1];
}

void uart_write(sys_device *, const void *frame, uint8_t size) { note("tx:" + hex(frame, size)); }

bool note_payload(sys_pid, sys_event_id, const sys_event_data *d) {
    note("rx:" + std::string(static_cast<const char *>(d->value), d->size));
    return true;
}

sys_device uart_device() {
    sys_device uart = make_device("uart", SYS_DEVICE_COMM, EV_A, frame_rx, nullptr);
    uart.tx_event = EV_B;
    uart.tx_processor = frame_tx;
    uart.write = uart_write;
    return uart;
}
} // namespace

TEST_F(Hal, CommTxProcessorFramesThePayloadWithAChecksum) {
    sys_device uart = uart_device();
    boot([&] {
        EXPECT_STATUS(SYS_OK, Sys_Register_Device(&uart));
        spawn([&] { EXPECT_STATUS(SYS_OK, Sys_Send_Event(EV_B, "hi!", 3)); });
    });
    settle();
    // 3 + 'h' + 'i' + '!' = 0xF5, so the checksum is 0x0B.
    EXPECT_EQ("tx:7e 03 68 69 21 0b", joined());
    EXPECT_EQ(0, uart.rejected);
}

TEST_F(Hal, CommRxProcessorChecksFramesAndRejectsCorruptedOnes) {
    sys_device uart = uart_device();
    boot([&] {
        Sys_Register_Device(&uart);
        Sys_Subscribe_to_Event(EV_A, SYS_PID_SYSTEM, note_payload, nullptr);
    });
    settle();
    auto receive = [&](std::vector<uint8_t> frame) { // as the UART's Rx interrupt would
        sys_status st = SYS_E_INVALID;
        irq([&] {
            st = Sys_Device_Input(&uart, frame.data(), static_cast<uint8_t>(frame.size()));
        });
        settle();
        EXPECT_STATUS(SYS_OK, st);
    };
    receive({0x7E, 0x03, 'h', 'i', '!', 0x0B});
    receive({0x7E, 0x03, 'h', 'j', '!', 0x0B}); // a flipped bit
    receive({0x7E, 0x04, 'h', 'i', '!', 0x0B}); // wrong length
    receive({0x7E, 0x02, 'o', 'k', static_cast<uint8_t>(-(2 + 'o' + 'k'))});
    EXPECT_EQ("rx:hi! rx:ok", joined());
    EXPECT_EQ(2, uart.rejected);
}

TEST_F(Hal, CommLoopbackDeliversATransmittedPayloadToAWaitingThread) {
    // The lower layer wires Tx to Rx, as a loopback cable would.
    static sys_device uart;
    uart = uart_device();
    uart.write = [](sys_device *dev, const void *frame, uint8_t size) {
        Sys_Device_Input(dev, frame, size);
    };
    char got[8] = {};
    uint8_t got_size = 0;
    boot([&] {
        Sys_Register_Device(&uart);
        spawn([&] {
            EXPECT_STATUS(SYS_OK, Sys_Wait_for_Event(EV_A, got, sizeof got, &got_size));
            note("got");
        });
        spawn([&] { Sys_Send_Event(EV_B, "ping", 4); });
    });
    settle();
    EXPECT_EQ("got", joined());
    EXPECT_EQ(4, got_size);
    EXPECT_EQ("ping", std::string(got, got_size));
}

namespace {
// The paper's one-pixel line-of-sight sensor: a camera frame (here 2x2 RGB
// pixels) becomes the one colour in front of the robot.
enum Colour : uint8_t { UNKNOWN = 1, WHITE, RED, GREEN };
constexpr uint8_t FRAME_BYTES = 12;

uint8_t one_pixel_sensor(sys_device *, const void *in, uint8_t size, void *out, uint8_t capacity) {
    if (size != FRAME_BYTES || capacity < 1) return 0;
    const uint8_t *px = static_cast<const uint8_t *>(in);
    int r = 0, g = 0, b = 0;
    for (int i = 0; i < FRAME_BYTES; i += 3) {
        r += px[i];
        g += px[i + 1];
        b += px[i + 2];
    }
    r /= 4, g /= 4, b /= 4;
    uint8_t c = UNKNOWN;
    if (r > 170 && g > 170 && b > 170)
        c = WHITE;
    else if (r > g + 60 && r > b + 60)
        c = RED;
    else if (g > r + 60 && g > b + 60)
        c = GREEN;
    *static_cast<uint8_t *>(out) = c;
    return 1;
}

bool note_colour(sys_pid, sys_event_id, const sys_event_data *d) {
    static const char *const names[] = {"?", "unknown", "white", "red", "green"};
    uint8_t c = *static_cast<const uint8_t *>(d->value);
    note(d->size != 1 ? "size" + std::to_string(d->size) : c <= GREEN ? names[c] : "bad");
    return true;
}
} // namespace

TEST_F(Hal, VirtualSensorReducesACameraFrameToOneColour) {
    sys_device camera = make_device("1px", SYS_DEVICE_INPUT, EV_A, one_pixel_sensor, nullptr);
    const uint8_t object[FRAME_BYTES] = {200, 30, 20, 180, 40, 40, 220, 10, 30, 190, 50, 20};
    const uint8_t robot[FRAME_BYTES] = {20, 200, 40, 30, 180, 30, 10, 210, 60, 40, 190, 20};
    const uint8_t wall[FRAME_BYTES] = {240, 240, 230, 250, 245, 240, 230, 235, 250, 245, 250, 240};
    const uint8_t dark[FRAME_BYTES] = {40, 40, 40, 30, 30, 35, 50, 45, 40, 20, 25, 30};
    boot([&] {
        Sys_Register_Device(&camera);
        Sys_Subscribe_to_Event(EV_A, SYS_PID_SYSTEM, note_colour, nullptr);
        spawn([&] {
            for (const uint8_t *frame : {object, robot, wall, dark})
                Sys_Device_Input(&camera, frame, FRAME_BYTES);
            Sys_Device_Input(&camera, wall, FRAME_BYTES - 3); // a truncated frame
        });
    });
    settle();
    EXPECT_EQ("red green white unknown", joined());
    EXPECT_EQ(1, camera.rejected);
}

TEST_F(Hal, RegisterDeviceRejectsNullDuplicatesAndAFullTable) {
    sys_device d[OS_CFG_MAX_DEVICES + 1];
    for (auto &dev : d) dev = make_device("d", SYS_DEVICE_INPUT, EV_A, nullptr, nullptr);
    sys_device bad_kind =
        make_device("bad", static_cast<sys_device_kind>(7), EV_A, nullptr, nullptr);
    std::vector<std::string> got;
    boot([&] {
        auto r = [&](sys_status st) { got.push_back(Sys_Status_Name(st)); };
        r(Sys_Register_Device(nullptr));
        r(Sys_Register_Device(&bad_kind));
        r(Sys_Register_Device(&d[0]));
        r(Sys_Register_Device(&d[0]));
        for (int i = 1; i < OS_CFG_MAX_DEVICES; i++) r(Sys_Register_Device(&d[i]));
        r(Sys_Register_Device(&d[OS_CFG_MAX_DEVICES])); // table full
        r(Sys_Unregister_Device(&d[1]));
        r(Sys_Unregister_Device(&d[1]));
        r(Sys_Unregister_Device(nullptr));
        r(Sys_Register_Device(&d[OS_CFG_MAX_DEVICES])); // a slot is free again
    });
    settle();
    EXPECT_EQ((std::vector<std::string>{"SYS_E_INVALID", "SYS_E_INVALID", "SYS_OK", "SYS_E_EXISTS",
                                        "SYS_OK", "SYS_OK", "SYS_OK", "SYS_E_POOL_FULL", "SYS_OK",
                                        "SYS_E_NOT_FOUND", "SYS_E_NOT_FOUND", "SYS_OK"}),
              got);
    EXPECT_EQ(1, stats().device_table_full);
}

TEST_F(Hal, RegisterDeviceRegistersItsEventsWithTheHalCapacity) {
    sys_device uart = uart_device();
    bool rx = false, tx = false;
    boot([&] {
        Sys_Register_Device(&uart);
        rx = Sys_IsEventRegistered(EV_A);
        tx = Sys_IsEventRegistered(EV_B);
        spawn([&] {
            uint8_t largest[OS_CFG_HAL_MAX_VALUE] = {};
            EXPECT_STATUS(SYS_OK, Sys_Send_Event(EV_A, largest, sizeof largest));
            EXPECT_STATUS(SYS_E_TOO_BIG, Sys_Send_Event(EV_A, largest, sizeof largest + 1));
            EXPECT_STATUS(SYS_E_INVALID, Sys_Set_TxProcessor(nullptr, frame_tx));
            sys_device in = make_device("in", SYS_DEVICE_INPUT, EV_C, nullptr, nullptr);
            EXPECT_STATUS(SYS_E_INVALID, Sys_Set_TxProcessor(&in, frame_tx));
            EXPECT_STATUS(SYS_OK, Sys_Set_TxProcessor(&uart, nullptr)); // plain copy
            Sys_Send_Event(EV_B, "raw", 3);
        });
    });
    settle();
    EXPECT_TRUE(rx);
    EXPECT_TRUE(tx);
    EXPECT_EQ("tx:72 61 77", joined());
}

// A device refused part-way (here: no subscription left for its command
// handler) leaves no event of its own registered behind.
TEST_F(Hal, ARefusedRegistrationLeavesNoEventBehind) {
    sys_device uart = uart_device(); // registers EV_A and EV_B, subscribes to EV_B
    sys_status st = SYS_OK;
    bool rx = true, tx = true, other = false;
    boot([&] {
        for (int k = 0; k < OS_CFG_MAX_SUBSCRIPTIONS; k++) { // fill the subscription pool
            sys_event_id e = (sys_event_id)(EV_C + k);
            Sys_Register_Event(e);
            Sys_Subscribe_to_Event(e, SYS_PID_SYSTEM, note_int16, nullptr);
        }
        st = Sys_Register_Device(&uart);
        rx = Sys_IsEventRegistered(EV_A);
        tx = Sys_IsEventRegistered(EV_B);
        other = Sys_IsEventRegistered(EV_C);
    });
    settle();
    EXPECT_STATUS(SYS_E_POOL_FULL, st);
    EXPECT_FALSE(rx) << "its receive event stayed registered";
    EXPECT_FALSE(tx) << "its transmit event stayed registered";
    EXPECT_TRUE(other) << "events registered before are left alone";
}

TEST_F(Hal, UnregisterDeviceStopsItsOutputPath) {
    sys_device left = make_device("left", SYS_DEVICE_OUTPUT, EV_B, nullptr, nullptr);
    sys_device right = make_device("right", SYS_DEVICE_OUTPUT, EV_C, nullptr, nullptr);
    left.write = right.write = motor_write;
    boot([&] {
        Sys_Register_Device(&left);
        Sys_Register_Device(&right);
        spawn([&] {
            Sys_Send_IntEvent(EV_B, 100);
            Sys_Send_IntEvent(EV_C, 100);
            EXPECT_STATUS(SYS_OK, Sys_Unregister_Device(&left));
            note("unregistered");
            EXPECT_STATUS(SYS_OK, Sys_Send_IntEvent(EV_B, 200)) << "the event itself stays";
            Sys_Send_IntEvent(EV_C, 200);
            EXPECT_STATUS(SYS_OK, Sys_Register_Device(&left));
            note("again");
            Sys_Send_IntEvent(EV_B, 300);
        });
    });
    settle();
    EXPECT_EQ("left=100 right=100 unregistered right=200 again left=300", joined());
}

TEST_F(Hal, EmptyReadingOfADeviceWithoutProcessorIsCopiedSafely) {
    // "No processor" means copy: an empty reading (a bare "pressed") is an
    // empty event, not a lost one (and no memcpy from NULL).
    sys_device button = make_device("button", SYS_DEVICE_INPUT, EV_A, nullptr, nullptr);
    boot([&] {
        Sys_Register_Device(&button);
        Sys_Subscribe_to_Event(EV_A, SYS_PID_SYSTEM, note_int16, nullptr);
    });
    settle();
    sys_status st = SYS_E_INVALID;
    irq([&] { st = Sys_Device_Input(&button, nullptr, 0); });
    settle();
    EXPECT_STATUS(SYS_OK, st);
    EXPECT_EQ("size0", joined()) << "an empty reading (a bare 'pressed') is an empty event";
}

TEST_F(Hal, ASecondOutputDeviceOnTheSameCommandIsRefused) {
    // One command event drives one device; a second registration that would
    // never be written is refused rather than silently dead.
    sys_device a = make_device("a", SYS_DEVICE_OUTPUT, EV_B, nullptr, nullptr);
    sys_device b = make_device("b", SYS_DEVICE_OUTPUT, EV_B, nullptr, nullptr);
    a.write = b.write = motor_write;
    sys_status second = SYS_E_INVALID;
    boot([&] {
        EXPECT_STATUS(SYS_OK, Sys_Register_Device(&a));
        second = Sys_Register_Device(&b);
        spawn([] { Sys_Send_IntEvent(EV_B, 7); });
    });
    settle();
    EXPECT_STATUS(SYS_E_EXISTS, second);
    EXPECT_EQ("a=7", joined());
}

TEST_F(Hal, RegistrationFromAnInterruptIsRefused) {
    static sys_device dev;
    dev = sys_device{"late", SYS_DEVICE_INPUT, EV_A, 0, nullptr, nullptr, nullptr, nullptr, 0};
    sys_status reg = SYS_OK, unreg = SYS_OK;
    boot([] {});
    irq([&] {
        reg = Sys_Register_Device(&dev);
        unreg = Sys_Unregister_Device(&dev);
    });
    EXPECT_STATUS(SYS_E_CONTEXT, reg);
    EXPECT_STATUS(SYS_E_CONTEXT, unreg);
}

TEST_F(Hal, ReadingGivesTheCallerTheValueItSendsAndReportsARejection) {
    sys_device prox = make_device("prox", SYS_DEVICE_INPUT, EV_A, linearise, &bare_table);
    int16_t mm = -1, rejected_mm = -1;
    uint8_t size = 0;
    uint8_t low_byte = 0;
    boot([&] {
        Sys_Register_Device(&prox);
        Sys_Subscribe_to_Event(EV_A, SYS_PID_SYSTEM, note_int16, nullptr);
        spawn([&] {
            uint16_t raw = 2000, too_far = 100;
            EXPECT_STATUS(SYS_OK, Sys_Device_Read(&prox, &raw, sizeof raw, &mm, sizeof mm, &size));
            EXPECT_STATUS(SYS_E_NOT_FOUND,
                          Sys_Device_Read(&prox, &too_far, sizeof too_far, &rejected_mm, sizeof rejected_mm, nullptr));
            raw = 1000; // 40 mm: one byte of room gets the first byte, the size says two
            EXPECT_STATUS(SYS_OK, Sys_Device_Read(&prox, &raw, sizeof raw, &low_byte, 1, &size));
            EXPECT_STATUS(SYS_E_INVALID, Sys_Device_Read(&prox, &raw, sizeof raw, nullptr, 2, nullptr));
        });
    });
    settle();
    EXPECT_EQ(20, mm);
    EXPECT_EQ(-1, rejected_mm) << "a rejected reading leaves the caller's value alone";
    EXPECT_EQ(2, size);
    int16_t forty = 40;
    EXPECT_EQ(reinterpret_cast<const uint8_t *>(&forty)[0], low_byte);
    EXPECT_EQ("20 40", joined()) << "each value read is also sent";
    EXPECT_EQ(1, prox.rejected);
}
