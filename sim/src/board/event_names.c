/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* An event's name for the warnings, not its number: the kernel's and the
 * robot's device events by their macros' names (kernel/include/openswarm/
 * event.h, the ports' kilobot.h and epuck.h), the app's by openswarm.json's
 * "events" as openswarm_app.h names them. The tool writes those names into
 * the firmware's section .openswarm.events, in the order of their ids (a
 * section no robot loads: no flash), which this reads. */
#include <fcntl.h>
#include <gelf.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "sim.h"

/* The events below SYS_EVENT_FIRST_FREE, by id, for each kind of robot;
 * the app's first id follows them. */
static const char *const kilobot_events[] = {
    "SYS_EVENT_1MS_TIMER", "SYS_EVENT_FAULT",   "KILOBOT_EVENT_LED",         "KILOBOT_EVENT_MOTORS",
    "KILOBOT_EVENT_IR_RX", "KILOBOT_EVENT_IR_TX", "KILOBOT_EVENT_LIGHT",     "KILOBOT_EVENT_VOLTAGE",
    "KILOBOT_EVENT_TEMPERATURE", "KILOBOT_EVENT_OHC"};
/* The e-puck's ports reserve 16 device events and use 8 (epuck.h). */
static const char *const epuck_events[] = {
    "SYS_EVENT_1MS_TIMER", "SYS_EVENT_FAULT", "EPUCK_EVENT_WHEELS",  "EPUCK_EVENT_RING_LEDS",
    "EPUCK_EVENT_BODY_LED", "EPUCK_EVENT_FRONT_LED", "EPUCK_EVENT_RGB_LEDS", "EPUCK_EVENT_PROXIMITY",
    "EPUCK_EVENT_CAMERA", "EPUCK_EVENT_SELECTOR", NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL};

typedef struct app_events {
    char *path;  /* the firmware they were read from */
    char *names; /* "EV_A\0EV_B\0", size bytes */
    size_t size;
} app_events;

static app_events app;

/* The section's bytes from the ELF at path (a fresh copy), or NULL. */
static char *section_of(const char *path, const char *wanted, size_t *size) {
    elf_version(EV_CURRENT);
    int fd = open(path, O_RDONLY);
    Elf *elf = fd < 0 ? NULL : elf_begin(fd, ELF_C_READ, NULL);
    size_t strings = 0;
    char *copy = NULL;
    if (elf != NULL && elf_getshdrstrndx(elf, &strings) == 0) {
        for (Elf_Scn *scn = NULL; copy == NULL && (scn = elf_nextscn(elf, scn)) != NULL;) {
            GElf_Shdr shdr;
            const char *name = gelf_getshdr(scn, &shdr) ? elf_strptr(elf, strings, shdr.sh_name) : NULL;
            Elf_Data *data = name && strcmp(name, wanted) == 0 ? elf_getdata(scn, NULL) : NULL;
            if (data == NULL || data->d_buf == NULL || data->d_size == 0) continue;
            copy = malloc(data->d_size + 1);
            if (copy == NULL) break;
            memcpy(copy, data->d_buf, data->d_size);
            copy[data->d_size] = '\0'; /* a last name cut short still ends */
            *size = data->d_size + 1;
        }
    }
    if (elf != NULL) elf_end(elf);
    if (fd >= 0) close(fd);
    return copy;
}

static void read_app_events(const char *path) {
    if (app.path != NULL && strcmp(app.path, path) == 0) return;
    free(app.path);
    free(app.names);
    memset(&app, 0, sizeof app);
    app.path = strdup(path);
    app.names = section_of(path, ".openswarm.events", &app.size);
}

/* The k-th of the app's names, or NULL. */
static const char *app_event(unsigned k) {
    for (size_t at = 0; app.names != NULL && at < app.size; k--) {
        if (k == 0) return app.names + at;
        at += strlen(app.names + at) + 1;
    }
    return NULL;
}

const char *event_name(const char *firmware, robot_kind kind, unsigned id, char *out, size_t size) {
    const char *const *ports = kind == ROBOT_EPUCK ? epuck_events : kilobot_events;
    unsigned first_free = kind == ROBOT_EPUCK ? sizeof epuck_events / sizeof *epuck_events
                                              : sizeof kilobot_events / sizeof *kilobot_events;
    const char *name = NULL;
    if (id < first_free) {
        name = ports[id];
    } else if (firmware != NULL) {
        read_app_events(firmware);
        name = app_event(id - first_free);
    }
    if (name != NULL && name[0] != '\0') snprintf(out, size, "%s (event %u)", name, id);
    else snprintf(out, size, "event %u", id);
    return out;
}
