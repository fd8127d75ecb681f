/* The paper's Listing 1 (object clustering) on the host port, in real time.
 *
 * A simulated camera feeds a frame every 100 ms to the one-pixel
 * line-of-sight sensor (a virtual sensor: a HAL pre-processor);
 * object_clustering turns the colour in front of the robot into wheel
 * speeds; a logging thread prints time:(left,right) every 250 ms. After
 * about 2 s the kernel is stopped and main prints a summary. */
#include <stdio.h>
#include <string.h>

#include "openswarm/kernel.h"

enum {
    SYS_IO_1PXSENSOR = SYS_EVENT_FIRST_FREE,
    SYS_LEFTMOTOR_SPEED,
    SYS_RIGHTMOTOR_SPEED
};

typedef enum { UNKNOWN = 1, WHITE, RED, GREEN } sys_colour;

/* Illustrative wheel speeds (steps/s); the paper takes its own from [10]. */
#define ROBOT_SPEED_L (-300) /* another robot ahead: turn away */
#define ROBOT_SPEED_R 300
#define OBJECT_SPEED_L 500 /* an object: push it */
#define OBJECT_SPEED_R 500
#define NOTHING_SPEED_L 400 /* nothing: search on a curve */
#define NOTHING_SPEED_R 250

#define FRAME_BYTES 12 /* 2x2 RGB pixels stand in for the 160x160 sub-frame */
#define RUN_MS 2000

static unsigned frames, decisions, log_lines;
static int16_t left_speed, right_speed; /* the paper's Sys_Get_MotorSpeed_Left/Right */

/* The virtual sensor: a whole frame becomes one colour. */
static uint8_t one_pixel_sensor(sys_device *dev, const void *in, uint8_t size, void *out,
                                uint8_t capacity) {
    const uint8_t *px = in;
    unsigned r = 0, g = 0, b = 0;
    sys_colour c = UNKNOWN;
    (void)dev;
    if (size != FRAME_BYTES || capacity < 1) return 0; /* a broken frame is no reading */
    for (int i = 0; i < FRAME_BYTES; i += 3) {
        r += px[i];
        g += px[i + 1];
        b += px[i + 2];
    }
    r /= 4, g /= 4, b /= 4;
    if (r > 170 && g > 170 && b > 170)
        c = WHITE;
    else if (r > g + 60 && r > b + 60)
        c = RED;
    else if (g > r + 60 && g > b + 60)
        c = GREEN;
    *(uint8_t *)out = (uint8_t)c;
    return 1;
}

/* A host has no wheels: the post-processor keeps the speed where the
 * logging thread reads it, and there is no lower layer to write to. */
static uint8_t store_speed(sys_device *dev, const void *in, uint8_t size, void *out,
                           uint8_t capacity) {
    if (size != sizeof(int16_t) || capacity < size) return 0;
    memcpy(dev->params, in, size);
    memcpy(out, in, size);
    return size;
}

static sys_device camera = {.name = "camera", .kind = SYS_DEVICE_INPUT,
                            .event = SYS_IO_1PXSENSOR, .processor = one_pixel_sensor};
static sys_device left_motor = {.name = "left motor", .kind = SYS_DEVICE_OUTPUT,
                                .event = SYS_LEFTMOTOR_SPEED, .processor = store_speed,
                                .params = &left_speed};
static sys_device right_motor = {.name = "right motor", .kind = SYS_DEVICE_OUTPUT,
                                 .event = SYS_RIGHTMOTOR_SPEED, .processor = store_speed,
                                 .params = &right_speed};

static bool object_clustering(sys_pid pid, sys_event_id event, const sys_event_data *data) {
    (void)pid, (void)event;
    switch (*(const uint8_t *)data->value) {
    case GREEN: /* another robot */
        Sys_Send_IntEvent(SYS_LEFTMOTOR_SPEED, ROBOT_SPEED_L);
        Sys_Send_IntEvent(SYS_RIGHTMOTOR_SPEED, ROBOT_SPEED_R);
        break;
    case RED: /* an object */
        Sys_Send_IntEvent(SYS_LEFTMOTOR_SPEED, OBJECT_SPEED_L);
        Sys_Send_IntEvent(SYS_RIGHTMOTOR_SPEED, OBJECT_SPEED_R);
        break;
    case WHITE: /* nothing, or a wall */
        Sys_Send_IntEvent(SYS_LEFTMOTOR_SPEED, NOTHING_SPEED_L);
        Sys_Send_IntEvent(SYS_RIGHTMOTOR_SPEED, NOTHING_SPEED_R);
        break;
    default: /* anything else: keep going as before */
        return true;
    }
    decisions++;
    return true; /* stay subscribed */
}

/* What the camera sees in turn, three frames each. */
static const uint8_t scenes[4][FRAME_BYTES] = {
    {240, 240, 230, 250, 245, 240, 230, 235, 250, 245, 250, 240}, /* white wall */
    {200, 30, 20, 180, 40, 40, 220, 10, 30, 190, 50, 20},         /* red object */
    {20, 200, 40, 30, 180, 30, 10, 210, 60, 40, 190, 20},         /* green robot */
    {40, 40, 40, 30, 30, 35, 50, 45, 40, 20, 25, 30}};            /* too dark to tell */

static void camera_thread(void) {
    for (;;) {
        Sys_Device_Input(&camera, scenes[(frames / 3) % 4], FRAME_BYTES);
        frames++;
        Sys_Sleep(100);
    }
}

/* Listing 1's wait250times, counting to 250 (the paper's `counter++ < 250`
 * accepts the 251st tick). */
static bool wait250times(const sys_event_data *data) {
    static uint8_t counter = 0;
    (void)data;
    if (++counter < 250) return false;
    counter = 0;
    return true;
}

static void logging_thread(void) {
    for (;;) {
        uint32_t now;
        /* The pair must not change halfway, and stdio must not be entered
         * by another of our threads (they share one POSIX thread). */
        Sys_Start_CriticalSection();
        printf("%lu:(%d,%d)\n", (unsigned long)Sys_Get_SystemTime(), left_speed, right_speed);
        fflush(stdout);
        log_lines++;
        Sys_End_CriticalSection();
        /* Ticks that pass while this thread runs are not counted: the
         * period is 250 ms plus the time it takes to print. */
        Sys_Wait_for_Condition(SYS_EVENT_1MS_TIMER, wait250times, &now, sizeof now, NULL);
    }
}

static void experiment_timer(void) {
    Sys_Sleep(RUN_MS);
    Sys_Stop_Kernel();
}

/* Listing 1's main, up to Sys_Start_Kernel. Registering a device
 * registers its events. */
static bool setup(void) {
    return Sys_Register_Device(&camera) == SYS_OK && Sys_Register_Device(&left_motor) == SYS_OK &&
           Sys_Register_Device(&right_motor) == SYS_OK &&
           Sys_Subscribe_to_Event(SYS_IO_1PXSENSOR, SYS_PID_SYSTEM, object_clustering, NULL) ==
               SYS_OK &&
           Sys_Start_Process(camera_thread) != SYS_PID_NONE &&
           Sys_Start_Process(logging_thread) != SYS_PID_NONE &&
           Sys_Start_Process(experiment_timer) != SYS_PID_NONE;
}

int main(void) {
    Sys_Init_Kernel();
    if (!setup()) {
        fprintf(stderr, "listing1: setup failed (see demo_config.h for the pool sizes)\n");
        return 1;
    }
    Sys_Start_Kernel();
    Sys_Run_SystemThread();
    printf("listing1: stopped at %lu ms: %u frames, %u decisions, %u log lines, speed (%d,%d)\n",
           (unsigned long)Sys_Get_SystemTime(), frames, decisions, log_lines, left_speed,
           right_speed);
    return 0;
}
