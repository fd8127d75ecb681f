// The C++ SDK on the robot: handlers that end their own subscription (a
// lambda with captures returning false, a method, an event without data's
// lambda) and a conditional wait with a timeout (avr.sdk_ending_handlers).
#include "openswarm/kilobot.h"
#include "openswarm/kilobot_sim.h"
#include "openswarm/openswarm.hpp"

using namespace openswarm;

static constexpr Event<uint8_t> level_event{SYS_EVENT_FIRST_FREE};
static constexpr Event<void> bell{SYS_EVENT_FIRST_FREE + 1};
static bool is_seven(const uint8_t &level) { return level == 7; }

struct Tally {
    uint8_t levels;
    bool count(const uint8_t &) { return ++levels < 2; } // ends at its second call
};

static void say(const char *what, uint32_t n) {
    sim_puts_P(what);
    sim_put_uint(n);
    sim_putc('\n');
}

int main() {
    Sys_Init_Kernel();
    kilobot_devices_init();
    level_event.enroll();
    bell.enroll();
    static Tally tally;
    level_event.subscribe<Tally, &Tally::count>(tally);
    static uint8_t rings;
    uint8_t &rung = rings;
    bell.subscribe([&rung] { return ++rung < 3; }); // ends at its third
    static uint8_t calls;
    uint8_t &count = calls;
    level_event.subscribe([&count](const uint8_t &level) {
        count++;
        uint8_t colour = KILOBOT_RGB(level, 0, 0);
        Sys_Send_Event(KILOBOT_EVENT_LED, &colour, 1);
        return level < 2; // shows 0, 1, 2, then ends its subscription
    });
    Thread::start([] {
        for (uint8_t level = 0; level < 4; level++) {
            level_event.send(level);
            bell.send();
            Thread::sleep(100);
        }
        say(PSTR("handler calls "), calls);
        say(PSTR("method calls "), tally.levels);
        say(PSTR("bell rings "), rings);
        uint8_t seen = 0;
        uint32_t from = now_ms();
        Status st = level_event.wait_until<&is_seven>(seen, 250);
        say(PSTR("wait_until status "), (uint8_t)-st);
        say(PSTR("after ms "), now_ms() - from);
    }, 128);
    Sys_Start_Kernel();
    Sys_Run_SystemThread();
    return 0;
}
