// The C++ SDK's lambdas: a handler with captures (a value and a
// reference: kept with a context binding) and a thread, written in place.
#include "openswarm/kilobot.h"
#include "openswarm/openswarm.hpp"

using namespace openswarm;

static constexpr Event<uint8_t> level_event{SYS_EVENT_FIRST_FREE};

int main() {
    Sys_Init_Kernel();
    kilobot_devices_init();
    level_event.enroll();
    static uint8_t top_levels;
    uint8_t &tops = top_levels;
    const uint8_t blue = 2; // the top level also lights blue, from the second time on
    level_event.subscribe([blue, &tops](const uint8_t &level) {
        if (level == 3) tops++;
        uint8_t colour = KILOBOT_RGB(level, 0, tops > 1 && level == 3 ? blue : 0);
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
