// {{name}}: blinky in C++ with the OpenSwarm SDK. A thread blinks the LED;
// a lambda subscribed to a typed event counts the blinks. openswarm.json
// declares the thread and the event: `openswarm build` turns them into
// openswarm_app.h, where the event is openswarm::events::blinked, an
// Event<uint16_t> (sending or handling another type does not compile), and
// blinker() keeps the C linkage the start-up code calls it by. It compiles
// to no more code than the C version (C++14, no standard library).
#include "openswarm/robot.h"
#include "openswarm_app.h"

using namespace openswarm;

static constexpr Event<uint8_t> led{ROBOT_EVENT_LED};
static uint16_t blinks;

void blinker() {
    for (uint16_t n = 1;; n++) {
        led.send(ROBOT_RGB(0, 3, 0));
        events::blinked.send(n);
        Thread::sleep(250);
        led.send(ROBOT_RGB(0, 0, 0));
        Thread::sleep(250);
    }
}

int main() {
    Sys_Init_Kernel();
    robot_devices_init();
    openswarm_app_start();
    events::blinked.subscribe([](const uint16_t &n) { blinks = n; });
    Sys_Start_Kernel();
    Sys_Run_SystemThread();
    return 0;
}
