/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
#include "world/epuck_link.h"

#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <poll.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

/* How long, in wall time, the world waits for a controller to take its
 * inputs or to answer them (issue 30: one that never answered blocked
 * the run, and `openswarm experiment`, forever). An exchange takes
 * milliseconds; a minute never trips on a loaded machine. */
static double wait_s = EPUCK_LINK_WAIT_S;

int epuck_link_wait_from_environment(void) {
    const char *text = getenv("OPENSWARM_LINK_TIMEOUT_S");
    if (text == NULL) return 0;
    char *end;
    double s = strtod(text, &end);
    if (end == text || *end != '\0' || !(s > 0 && s <= 86400)) {
        fprintf(stderr, "openswarm-sim: OPENSWARM_LINK_TIMEOUT_S=%.40s: expected seconds above 0, at most "
                        "86400 (how long the world waits for an e-puck controller's answer, in wall time; "
                        "default %g): give e.g. OPENSWARM_LINK_TIMEOUT_S=120, or unset it\n",
                text, (double)EPUCK_LINK_WAIT_S);
        return -1;
    }
    wait_s = s;
    return 0;
}

static double now_s(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + t.tv_nsec / 1e9;
}

enum { IO_DONE, IO_ENDED, IO_LATE };

/* size bytes through the non-blocking fd, waiting at most wait_s for
 * each to move: IO_ENDED at end of file or an error (errno), IO_LATE
 * when the time ran out. */
static int timed_io(int fd, void *buffer, size_t size, int writing) {
    double deadline = now_s() + wait_s;
    for (size_t done = 0; done < size;) {
        ssize_t n = writing ? write(fd, (const char *)buffer + done, size - done)
                            : read(fd, (char *)buffer + done, size - done);
        if (n > 0) {
            done += (size_t)n;
            continue;
        }
        if (n == 0) return IO_ENDED;
        if (errno == EINTR) continue;
        if (errno != EAGAIN && errno != EWOULDBLOCK) return IO_ENDED;
        double left = deadline - now_s();
        if (left <= 0) return IO_LATE;
        struct pollfd p = {fd, (short)(writing ? POLLOUT : POLLIN), 0};
        if (poll(&p, 1, (int)ceil(left * 1000)) < 0 && errno != EINTR) return IO_ENDED;
    }
    return IO_DONE;
}

/* What the world was waiting for, for a message. */
static const char *awaited(const epuck_link *l, char *text, size_t size, int writing) {
    if (l->stopping) snprintf(text, size, "the request to stop");
    else if (l->t_ms < 0) snprintf(text, size, "at start-up (its first answer, before any input)");
    else snprintf(text, size, "the step at %.2f s%s", l->t_ms / 1000.0, writing ? " (it read none of its inputs)" : "");
    return text;
}

/* The controller and whatever it started (its process group), killed and
 * reaped. */
static void kill_controller(epuck_link *l) {
    if (l->pid <= 0) return;
    kill(-l->pid, SIGKILL);
    kill(l->pid, SIGKILL);
    waitpid(l->pid, NULL, 0);
    l->pid = 0;
    close(l->to);
    close(l->from);
}

/* The controller's end, once its output ended: it exits then, or is
 * killed when it has not within the wait (it closed its output and went
 * on). */
static pid_t reap(pid_t pid, int *status) {
    double deadline = now_s() + wait_s;
    for (;;) {
        pid_t done = waitpid(pid, status, WNOHANG);
        if (done != 0) return done;
        if (now_s() > deadline) {
            kill(-pid, SIGKILL);
            kill(pid, SIGKILL);
            return waitpid(pid, status, 0);
        }
        usleep(10000);
    }
}

/* Why the controller is gone, reaped. */
static void report_gone(epuck_link *l, const char *doing) {
    int status = 0;
    pid_t done = l->pid > 0 ? reap(l->pid, &status) : -1;
    l->pid = 0;
    if (done > 0 && WIFEXITED(status))
        fprintf(stderr, "openswarm-sim: robot %d's controller %s exited with status %d while %s\n",
                l->index, l->controller, WEXITSTATUS(status), doing);
    else if (done > 0 && WIFSIGNALED(status))
        fprintf(stderr, "openswarm-sim: robot %d's controller %s was killed by signal %d (%s) while %s\n",
                l->index, l->controller, WTERMSIG(status), strsignal(WTERMSIG(status)), doing);
    else
        fprintf(stderr, "openswarm-sim: robot %d's controller %s stopped answering while %s\n",
                l->index, l->controller, doing);
}

/* A controller that let the time run out: named, with what it did not
 * answer, and killed. */
static void report_late(epuck_link *l, int writing) {
    char what[96];
    fprintf(stderr, "openswarm-sim: robot %d's controller %s did not answer %s within %g s of wall time: "
                    "it hangs (a loop that never waits, a read of its own standard input, a sleep) or is "
                    "not built for the world (PORT epuck_world); it was killed and the run stops. Run it "
                    "alone under gdb to see where it waits; a machine that slow may wait longer with "
                    "OPENSWARM_LINK_TIMEOUT_S=SECONDS\n",
            l->index, l->controller, awaited(l, what, sizeof what, writing), wait_s);
    kill_controller(l);
}

/* Any failed exchange: reported, and the controller gone. */
static int failed(epuck_link *l, int io, int writing) {
    if (io == IO_LATE) {
        report_late(l, writing);
    } else {
        report_gone(l, writing ? "taking its inputs" : "running");
        close(l->to);
        close(l->from);
    }
    return -1;
}

int epuck_link_is_epuck2_image(const char *path) {
    unsigned char header[20];
    FILE *f = fopen(path, "rb");
    if (f == NULL) return 0;
    size_t n = fread(header, 1, sizeof header, f);
    fclose(f);
    /* ELF, 32-bit, little-endian, e_machine (at 18) EM_ARM = 40 */
    return n == sizeof header && memcmp(header, "\177ELF\1\1", 6) == 0 && header[18] == 40 && header[19] == 0;
}

/* In the controller's child: QEMU running the e-puck2 image (board world)
 * with the link on its standard input and output through semihosting, the
 * robot's index as its --id, its console appended to our standard error
 * (appended: a log file there is not truncated), every instruction 8 ns
 * of virtual time (-icount), as docs/world.md's script runs it. Returns
 * only if QEMU cannot be run, after saying how to install it. */
static void exec_qemu(const char *image, int index) {
    char semihosting[96];
    snprintf(semihosting, sizeof semihosting, "enable=on,target=native,arg=app,arg=--id=%d", index);
    execlp("qemu-system-arm", "qemu-system-arm", "-M", "netduinoplus2", "-display", "none", "-monitor", "none",
           "-chardev", "file,id=console,path=/dev/stderr,append=on", "-serial", "chardev:console",
           "-semihosting-config", semihosting, "-icount", "shift=3,align=off,sleep=off", "-kernel", image,
           (char *)NULL);
    fprintf(stderr, "openswarm-sim: cannot run qemu-system-arm for robot %d's e-puck2 image %s: %s: sudo "
                    "apt-get install qemu-system-arm\n", index, image, strerror(errno));
    _exit(127);
}

int epuck_link_start(epuck_link *l, const char *controller, int under_qemu, int index, epuck_world_output *first) {
    int down[2], up[2];
    l->index = index;
    l->controller = controller;
    l->t_ms = -1;
    l->stopping = 0;
    signal(SIGPIPE, SIG_IGN); /* a controller that died is reported, not fatal */
    if (pipe(down) != 0 || pipe(up) != 0) {
        fprintf(stderr, "openswarm-sim: cannot start robot %d's controller: %s\n", index, strerror(errno));
        return -1;
    }
    l->pid = fork();
    if (l->pid == 0) {
        setpgid(0, 0); /* its own group: killed whole if it hangs, a shell's children too */
        dup2(down[0], STDIN_FILENO);
        dup2(up[1], STDOUT_FILENO);
        close(down[0]), close(down[1]), close(up[0]), close(up[1]);
        char id[16]; /* the robot's robot_id() (ports/epuck/host/src/robot_world.c) */
        snprintf(id, sizeof id, "%d", index);
        setenv("OPENSWARM_ROBOT_ID", id, 1);
        if (under_qemu) exec_qemu(controller, index);
        execl(controller, controller, (char *)NULL);
        fprintf(stderr, "openswarm-sim: cannot run %s: %s\n", controller, strerror(errno));
        _exit(127);
    }
    close(down[0]);
    close(up[1]);
    l->to = down[1];
    l->from = up[0];
    if (l->pid < 0) {
        fprintf(stderr, "openswarm-sim: cannot start robot %d's controller: %s\n", index, strerror(errno));
        close(l->to);
        close(l->from);
        return -1;
    }
    setpgid(l->pid, l->pid); /* as the child does: whichever runs first */
    /* the world's ends only: the controller's are other open files */
    fcntl(l->to, F_SETFL, fcntl(l->to, F_GETFL) | O_NONBLOCK);
    fcntl(l->from, F_SETFL, fcntl(l->from, F_GETFL) | O_NONBLOCK);
    return epuck_link_receive(l, first);
}

int epuck_link_send(epuck_link *l, const epuck_world_input *in, const uint16_t *pixels) {
    size_t n_pixels = (size_t)in->frame_width * in->frame_height;
    int io = timed_io(l->to, (void *)in, sizeof *in, 1);
    if (io == IO_DONE && n_pixels) io = timed_io(l->to, (void *)pixels, n_pixels * sizeof *pixels, 1);
    return io == IO_DONE ? 0 : failed(l, io, 1);
}

int epuck_link_receive(epuck_link *l, epuck_world_output *out) {
    int io = timed_io(l->from, out, sizeof *out, 0);
    if (io != IO_DONE) return failed(l, io, 0);
    if (out->magic != EPUCK_LINK_MAGIC) {
        fprintf(stderr, "openswarm-sim: robot %d's controller %s answered 0x%08x, not an e-puck link "
                        "record: build it for the world (PORT epuck_world), and let it print only "
                        "to stderr\n",
                l->index, l->controller, (unsigned)out->magic);
        return -1;
    }
    return 0;
}

int epuck_link_stop(epuck_link *l) {
    if (l->pid <= 0) return -1;
    epuck_world_input stop = {EPUCK_LINK_MAGIC, 0, EPUCK_LINK_STOP, 0, {0}, {0}, 0, 0};
    epuck_world_output last;
    l->stopping = 1;
    if (epuck_link_send(l, &stop, NULL) != 0 || epuck_link_receive(l, &last) != 0) {
        kill_controller(l); /* one that answered nonsense is still there */
        return -1;
    }
    /* An end of file instead: a controller without a kernel, none to send. */
    l->has_losses = timed_io(l->from, &l->losses, sizeof l->losses, 0) == IO_DONE &&
                    l->losses.magic == EPUCK_LINK_LOSSES_MAGIC;
    close(l->to);
    close(l->from);
    int status = 0;
    if (waitpid(l->pid, &status, 0) < 0) return -1;
    l->pid = 0;
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}
