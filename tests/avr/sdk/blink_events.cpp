// Blink with events, in C++ with the SDK: the twin of blink_events.c.
#include "openswarm/kilobot.h"
#include "openswarm/openswarm.hpp"

using namespace openswarm;

static constexpr Event<uint8_t> level_event{SYS_EVENT_FIRST_FREE};

static void show_level(const uint8_t &level) {
    uint8_t colour = KILOBOT_RGB(0, level, 0);
    Sys_Send_Event(KILOBOT_EVENT_LED, &colour, 1);
}

static void pulse() {
    for (uint8_t level = 0;; level = (uint8_t)((level + 1) & 3)) {
        {
            CriticalSection guard;
            level_event.send(level);
        }
        Thread::sleep(100);
    }
}

int main() {
    Sys_Init_Kernel();
    kilobot_devices_init();
    level_event.enroll();
    level_event.subscribe<&show_level>();
    Thread::start(pulse);
    Sys_Start_Kernel();
    Sys_Run_SystemThread();
    return 0;
}
