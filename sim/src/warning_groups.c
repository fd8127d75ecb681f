/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* The end-of-run warnings, each said once for every robot that gave it: a
 * world of 1000 robots running one firmware refuses the same subscription
 * 1000 times, and 1000 copies of one line bury the rest ("[robots 0-999]
 * warning: ..."). Warnings are noted while the robots are reported on, and
 * printed together, in the order each was first noted. */
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "sim.h"

typedef struct warning_group {
    char *text;
    int *robots; /* ascending: robots are noted in order */
    int n_robots, room;
} warning_group;

static warning_group *groups;
static int n_groups, groups_room;

static void *grown(void *items, int *room, size_t item_size) {
    int wanted = *room ? 2 * *room : 8;
    void *more = realloc(items, (size_t)wanted * item_size);
    if (more == NULL) {
        fprintf(stderr, "openswarm-sim: out of memory for the end-of-run warnings\n");
        exit(EXIT_FAILURE);
    }
    *room = wanted;
    return more;
}

static warning_group *group_of(const char *text) {
    for (int i = 0; i < n_groups; i++)
        if (strcmp(groups[i].text, text) == 0) return &groups[i];
    if (n_groups == groups_room) groups = grown(groups, &groups_room, sizeof *groups);
    warning_group *g = &groups[n_groups++];
    memset(g, 0, sizeof *g);
    g->text = strdup(text);
    if (g->text == NULL) {
        fprintf(stderr, "openswarm-sim: out of memory for the end-of-run warnings\n");
        exit(EXIT_FAILURE);
    }
    return g;
}

void warning_note(int robot_index, const char *format, ...) {
    char text[1024];
    va_list args;
    va_start(args, format);
    vsnprintf(text, sizeof text, format, args);
    va_end(args);
    warning_group *g = group_of(text);
    if (robot_index < 0) return; /* a run of one robot: no robots to name */
    if (g->n_robots == g->room) g->robots = grown(g->robots, &g->room, sizeof *g->robots);
    g->robots[g->n_robots++] = robot_index;
}

/* "robot 3", "robots 0-999", "robots 0, 2, 5-9" into out. */
static void robots_named(const warning_group *g, char *out, size_t size) {
    size_t used = (size_t)snprintf(out, size, "robot%s ", g->n_robots == 1 ? "" : "s");
    for (int i = 0; i < g->n_robots; i++) {
        if (used + 32 > size) { /* no room for another range: the rest as one word */
            snprintf(out + used, size - used, ", ...");
            return;
        }
        int first = g->robots[i];
        while (i + 1 < g->n_robots && g->robots[i + 1] == g->robots[i] + 1) i++;
        const char *comma = first == g->robots[0] ? "" : ", ";
        if (g->robots[i] == first) used += (size_t)snprintf(out + used, size - used, "%s%d", comma, first);
        else used += (size_t)snprintf(out + used, size - used, "%s%d-%d", comma, first, g->robots[i]);
    }
}

int warnings_print(void) {
    int printed = n_groups;
    for (int i = 0; i < n_groups; i++) {
        warning_group *g = &groups[i];
        char robots[256] = "";
        if (g->n_robots > 0) {
            char names[240];
            robots_named(g, names, sizeof names);
            snprintf(robots, sizeof robots, "[%s] ", names);
        }
        fprintf(stderr, "openswarm-sim: %swarning: %s\n", robots, g->text);
        free(g->text);
        free(g->robots);
    }
    free(groups);
    groups = NULL;
    n_groups = groups_room = 0;
    return printed;
}
