/* {{name}}: every robot counts its neighbours, with the OpenSwarm API.
 *  - a beacon thread broadcasts the robot's id on IR twice a second;
 *  - an event handler notes who it heard and how far away (openswarm.json
 *    gives the IR device the "distance" processor, which turns the two gain
 *    readings into millimetres);
 *  - a census thread counts, once a second exactly, the robots heard in the
 *    last two seconds and sends the count as an event (EV_NEIGHBOURS);
 *  - that event's handler shows it on the LED (red: alone, yellow: one
 *    neighbour, green: two or more) and prints it with the nearest one.
 * openswarm.json declares the threads, the event and the IR processor:
 * `openswarm build` turns them into openswarm_app.h and
 * openswarm_app_start(). */
#include <stdio.h>

#include "openswarm/kernel.h"
#include "openswarm/kilobot.h"
#include "openswarm/robot.h"
#include "openswarm_app.h"

#define BEACON_MS 500u
#define CENSUS_MS 1000u
#define FORGET_MS 2000u
#define MAX_NEIGHBOURS 8u
/* Our message's type (byte 9): the overhead controller's are 0x80 and up. */
#define HELLO 1u

typedef struct neighbour {
    uint16_t id; /* 0: a free entry */
    uint8_t distance_mm;
    uint32_t heard_ms;
} neighbour;

/* Written by the handler, read by the census in a critical section. */
static neighbour neighbours[MAX_NEIGHBOURS];

/* The frame's data bytes 0-1 carry the sender's id, little-endian; the
 * IR device's Tx processor adds the CRC. */
void beacon(void) {
    uint16_t id = robot_id();
    uint8_t frame[10] = {(uint8_t)id, (uint8_t)(id >> 8), 0, 0, 0, 0, 0, 0, 0, HELLO};
    /* Robots switched on together would always send together and collide:
     * each starts at its own offset. */
    Sys_Sleep(id * 37u % BEACON_MS);
    uint32_t wake = Sys_Get_SystemTime();
    for (;;) {
        Sys_Send_Event(KILOBOT_EVENT_IR_TX, frame, sizeof frame);
        Sys_Sleep_Until(&wake, BEACON_MS);
    }
}

/* The entry for id: its own, else a free one, else the one heard longest ago. */
static neighbour *entry_for(uint16_t id) {
    neighbour *oldest = &neighbours[0];
    for (neighbour *n = neighbours; n != &neighbours[MAX_NEIGHBOURS]; n++) {
        if (n->id == id) return n;
        if (n->id == 0 && oldest->id != 0) oldest = n;
        if (oldest->id != 0 && n->heard_ms < oldest->heard_ms) oldest = n;
    }
    return oldest;
}

static bool heard(sys_pid pid, sys_event_id event, const sys_event_data *data) {
    (void)pid;
    (void)event;
    const kilobot_ir_rx *rx = data->value;
    if (rx->frame[9] != HELLO) return true; /* another app's message */
    uint16_t id = (uint16_t)(rx->frame[0] | rx->frame[1] << 8);
    neighbour *n = entry_for(id);
    n->id = id;
    n->distance_mm = rx->distance_mm;
    n->heard_ms = Sys_Get_SystemTime();
    return true;
}

typedef struct census_result {
    uint8_t count;
    uint8_t nearest_mm; /* 255 when it heard nobody */
} census_result;
static census_result last;

void census(void) {
    uint32_t wake = Sys_Get_SystemTime();
    for (;;) {
        Sys_Sleep_Until(&wake, CENSUS_MS);
        census_result r = {0, 255};
        Sys_Start_CriticalSection(); /* no handler changes the table meanwhile */
        for (const neighbour *n = neighbours; n != &neighbours[MAX_NEIGHBOURS]; n++) {
            if (n->id == 0 || wake - n->heard_ms > FORGET_MS) continue;
            r.count++;
            if (n->distance_mm < r.nearest_mm) r.nearest_mm = n->distance_mm;
        }
        last = r;
        Sys_End_CriticalSection();
        Sys_Send_Event(EV_NEIGHBOURS, &r.count, sizeof r.count);
    }
}

static bool show(sys_pid pid, sys_event_id event, const sys_event_data *data) {
    (void)pid;
    (void)event;
    uint8_t count = *(const uint8_t *)data->value;
    uint8_t colour = count == 0 ? ROBOT_RGB(3, 0, 0) : count == 1 ? ROBOT_RGB(3, 3, 0) : ROBOT_RGB(0, 3, 0);
    Sys_Send_Event(ROBOT_EVENT_LED, &colour, 1);
    if (count == 0)
        printf("robot %u: alone\n", robot_id());
    else
        printf("robot %u: neighbours %u, nearest %u mm\n", robot_id(), count, last.nearest_mm);
    return true;
}

int main(void) {
    Sys_Init_Kernel();
    robot_devices_init();
    robot_console_init();
    openswarm_app_start();
    Sys_Subscribe_to_Event(KILOBOT_EVENT_IR_RX, SYS_PID_SYSTEM, heard, NULL);
    Sys_Subscribe_to_Event(EV_NEIGHBOURS, SYS_PID_SYSTEM, show, NULL);
    Sys_Start_Kernel();
    Sys_Run_SystemThread();
    return 0;
}
