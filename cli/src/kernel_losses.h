/* What the kernel lost or refused without failing, for the warnings at
 * the end of a run: each counter of openswarm/fault.h's sys_stats that
 * means a loss, what a non-zero count means and what to do. Shared by
 * openswarm-sim (a Kilobot's or a native robot's counters, C) and the
 * tool's QEMU runs (an e-puck2's, C++), so both say the same. */
#ifndef OPENSWARM_KERNEL_LOSSES_H
#define OPENSWARM_KERNEL_LOSSES_H

/* sys_stats' counters, in order (the queue's peak byte follows them). */
#define KERNEL_LOSS_COUNTERS 12
/* The robots whose set-up the fixes name: the index of what_on, fix_on. */
enum { KERNEL_LOSS_KILOBOT = 0, KERNEL_LOSS_EPUCK = 1 };

/* A counter by its index in sys_stats; each part's words for a Kilobot
 * and an e-puck follow it, where the robots differ (their device set-up). */
typedef struct kernel_loss {
    unsigned index;
    const char *what, *what_on[2];
    const char *fix, *fix_on[2];
} kernel_loss;

/* A number at or past the event pool's size is refused by
 * Sys_Register_Event without a count, so its subscriptions are the only
 * trace: the counters cannot tell it from an event not registered yet. */
#define PAST_THE_POOL                                                                                \
    "; an event numbered past the pool (ids from 0 to \"max_events\" - 1) is never registered: "   \
    "raise \"max_events\" in openswarm.json's \"kernel\" (docs/openswarm-json.md)"

static const kernel_loss kernel_losses[] = {
    {0, "thread start(s) refused: no free thread slot", {"", ""},
     "raise \"max_threads\" in openswarm.json's \"kernel\", or declare the threads in its \"threads\"", {"", ""}},
    {1, "thread start(s) refused: no room for a stack", {"", ""},
     "raise \"stack_pool\" in openswarm.json's \"kernel\", or give the threads smaller \"stack\"s", {"", ""}},
    {2, "event registration(s) refused: no room for the event's data, its handlers never run",
     {" (a kilolib program's pool holds kilolib's own: kilobot_sensors_init() needs 6 bytes more)", ""},
     "declare the app's events in openswarm.json's \"events\" (the pool is sized for them) or "
     "raise \"event_data\" in its \"kernel\"", {"", ""}},
    {3, "subscription(s) refused: every subscription slot in use, those handlers never run", {"", ""},
     "raise \"max_subscriptions\" in openswarm.json's \"kernel\"", {"", ""}},
    {4, "event send(s) refused: the event queue was full, those occurrences are lost", {"", ""},
     "raise \"event_queue\" in openswarm.json's \"kernel\", or send less often", {"", ""}},
    {5, "device registration(s) refused: no free device slot",
     {" (a kilolib program gets kilolib's own few, kilobot_sensors_init() needs 3 more)",
      " (epuck_devices_init() registers 8)"},
     "raise \"max_devices\" in openswarm.json's \"kernel\"", {"", ""}},
    {6, "queued event(s) discarded: their event was unregistered before they were dispatched", {"", ""},
     "unregister an event only once its last occurrence is handled", {"", ""}},
    {11, "subscription(s) refused: the event was not registered, the handler never runs",
     {" (a device's event, e.g. KILOBOT_EVENT_LIGHT, is registered by its init)",
      " (a device's event, e.g. EPUCK_EVENT_PROXIMITY, is registered by epuck_devices_init())"},
     "register the event before subscribing to it: call ",
     {"kilobot_sensors_init() for a sensor's event, openswarm_app_start() for openswarm.json's, or "
      "Sys_Register_Event, first" PAST_THE_POOL,
      "epuck_devices_init() for a device's event, openswarm_app_start() for openswarm.json's, or "
      "Sys_Register_Event, first" PAST_THE_POOL}},
};
#define KERNEL_LOSSES (sizeof kernel_losses / sizeof kernel_losses[0])

#endif
