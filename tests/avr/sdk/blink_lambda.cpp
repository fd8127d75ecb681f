// The C++ SDK's lambdas: a handler and a thread written in place.
#include "openswarm/kilobot.h"
#include "openswarm/openswarm.hpp"

using namespace openswarm;

static constexpr Event<uint8_t> level_event{SYS_EVENT_FIRST_FREE};

int main() {
    Sys_Init_Kernel();
    kilobot_devices_init();
    level_event.enroll();
    level_event.subscribe([](const uint8_t &level) {
        uint8_t colour = KILOBOT_RGB(level, 0, 0);
        Sys_Send_Event(KILOBOT_EVENT_LED, &colour, 1);
    });
    Thread::start([] {
        for (uint8_t level = 0;; level = (uint8_t)((level + 1) & 3)) {
            level_event.send(level);
            Thread::sleep(100);
        }
    });
    Sys_Start_Kernel();
    Sys_Run_SystemThread();
    return 0;
}
