// {{name}}: blinky in C++ with the OpenSwarm SDK. A thread blinks the LED;
// a lambda subscribed to a typed event counts the blinks. It compiles to
// no more code than the C version (C++14, no standard library).
#include "openswarm/robot.h"
#include "openswarm/openswarm.hpp"

using namespace openswarm;

static constexpr Event<uint8_t> led{ROBOT_EVENT_LED};
static constexpr Event<uint16_t> blinked{SYS_EVENT_FIRST_FREE};
static uint16_t blinks;

static void blinker() {
    for (uint16_t n = 1;; n++) {
        led.send(ROBOT_RGB(0, 3, 0));
        blinked.send(n);
        Thread::sleep(250);
        led.send(ROBOT_RGB(0, 0, 0));
        Thread::sleep(250);
    }
}

int main() {
    Sys_Init_Kernel();
    robot_devices_init();
    blinked.enroll();
    blinked.subscribe([](const uint16_t &n) { blinks = n; });
    Thread::start(blinker);
    Sys_Start_Kernel();
    Sys_Run_SystemThread();
    return 0;
}
