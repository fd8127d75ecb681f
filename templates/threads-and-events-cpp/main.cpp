// {{name}}: the OpenSwarm paper's Listing 1 on a Kilobot, with the C++ SDK.
//  - a computing thread counts primes without ever yielding (it is
//    preempted every 10 ms, so the rest still runs);
//  - a reactive handler turns every colour reading of a virtual sensor into
//    motor speeds, cooperatively, between threads;
//  - a logging thread prints time, primes and speeds every 250 ms, waiting
//    for the 250th occurrence of the 1 ms timer event.
// C++14 without the standard library, so it builds with avr-g++.
#include "debug.h"
#include "openswarm/kilobot.h"
#include "openswarm/openswarm.hpp"

using namespace openswarm;

enum : int16_t { nothing, object, robot }; // what the sensor sees

static constexpr Event<int16_t> colour{SYS_EVENT_FIRST_FREE};
static constexpr Event<kilobot_motors> motors{KILOBOT_EVENT_MOTORS};
static constexpr Event<uint32_t> one_ms{SYS_EVENT_1MS_TIMER}; // data: the time in ms

static volatile uint32_t primes; // volatile: the computing loop must store it
static kilobot_motors speeds;

static void compute() {
    for (uint32_t n = 2;; n++) {
        uint32_t d = 2;
        while (d * d <= n && n % d != 0) d++;
        if (d * d > n) primes++;
    }
}

// The virtual one-pixel sensor: a colour every 100 ms.
static void sensor() {
    for (uint8_t i = 0;; i++) {
        Thread::sleep(100);
        colour.send(i % 3);
    }
}

static void steer(const int16_t &seen) {
    kilobot_motors m{0, 0};
    if (seen == object) m.left = m.right = kilobot_calib.straight_left; // push it
    if (seen == robot) m.left = kilobot_calib.turn_left;                // avoid it
    speeds = m;
    motors.send(m);
}

static bool every_250th(const uint32_t &) {
    static uint8_t count;
    if (++count < 250) return false;
    count = 0;
    return true;
}

static void logger() {
    for (;;) {
        uint32_t tick;
        one_ms.wait_until<every_250th>(tick);
        uint32_t counted;
        kilobot_motors shown;
        {
            // A 4-byte count and a pair of speeds are read in several
            // instructions: no thread switch or handler may change them midway.
            CriticalSection guard;
            counted = primes;
            shown = speeds;
        }
        printf("%lu:(%u,%u) primes %lu\n", (unsigned long)now_ms(), shown.left, shown.right,
               (unsigned long)counted);
    }
}

int main() {
    Sys_Init_Kernel();
    kilobot_devices_init();
    debug_init();
    colour.enroll();
    colour.subscribe<steer>(); // called directly: costs what a C handler costs
    Thread::start(compute);
    Thread::start(sensor);
    Thread::start(logger, 160); // printf needs room
    Sys_Start_Kernel();
    Sys_Run_SystemThread();
    return 0;
}
