/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* video.mp4: the frames video_clock.c asks for, piped raw to ffmpeg at
 * the video's frame rate, so no frame ever lands on the disk. ffmpeg
 * writes video.mp4.part, renamed to video.mp4 once it exits well
 * (part_file.c).
 * H.264 (libx264) when this ffmpeg has it, MPEG-4 part 2 otherwise;
 * yuv420p so that every player plays it. */
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "output/output_parts.h"

/* Whether `program` is an executable file in one of PATH's folders. */
static int on_path(const char *program)
{
    const char *path = getenv("PATH");
    if (!path)
        return 0;
    char candidate[4096];
    while (*path) {
        size_t len = strcspn(path, ":");
        snprintf(candidate, sizeof candidate, "%.*s/%s", (int)(len ? len : 1),
                 len ? path : ".", program);
        if (access(candidate, X_OK) == 0)
            return 1;
        path += len;
        if (*path == ':')
            path++;
    }
    return 0;
}

static int has_libx264(void)
{
    FILE *f = popen("ffmpeg -hide_banner -loglevel error -encoders 2>/dev/null", "r");
    if (!f)
        return 0;
    char line[256];
    int found = 0;
    while (fgets(line, sizeof line, f))
        if (strstr(line, " libx264 "))
            found = 1;
    pclose(f);
    return found;
}

/* `path` in single quotes for the shell ffmpeg runs in. */
static char *shell_quoted(const char *path)
{
    size_t n = 3;
    for (const char *c = path; *c; c++)
        n += *c == '\'' ? 4 : 1;
    char *q = malloc(n), *o = q;
    if (!q)
        return NULL;
    *o++ = '\'';
    for (const char *c = path; *c; c++) {
        if (*c == '\'') {
            memcpy(o, "'\\''", 4);
            o += 4;
        } else {
            *o++ = *c;
        }
    }
    *o++ = '\'';
    *o = 0;
    return q;
}

/* Cairo's RGB24 pixels are 32-bit words 0xXXRRGGBB in the host's order. */
static const char *cairo_pixel_format(void)
{
    const uint32_t one = 1;
    return *(const uint8_t *)&one ? "bgr0" : "0rgb";
}

/* While frames are written, a dead ffmpeg must give a write error, not a
 * SIGPIPE that ends the simulator. */
static struct sigaction previous_sigpipe;

int video_check(void)
{
    if (on_path("ffmpeg"))
        return 0;
    const char *path = getenv("PATH");
    fprintf(stderr, "openswarm-sim: --video needs ffmpeg: apt-get install ffmpeg, or drop --video "
                    "(none in the PATH's folders: %.200s)\n",
            path ? path : "not set");
    return -1;
}

/* `command` by the shell, reading what the returned stream writes. In a
 * process group of its own: Ctrl-C at the terminal signals the
 * simulator's group, and the simulator then finishes the video
 * (interrupt.h) rather than see ffmpeg stop half-way. */
static FILE *start_ffmpeg(const char *command, pid_t *pid)
{
    int fds[2];
    if (pipe(fds) != 0)
        return NULL;
    fcntl(fds[1], F_SETFD, FD_CLOEXEC); /* later children (e-puck controllers) must not hold it open */
    fflush(NULL); /* the child must not inherit unwritten output */
    *pid = fork();
    if (*pid == 0) {
        setpgid(0, 0);
        dup2(fds[0], STDIN_FILENO);
        close(fds[0]);
        execl("/bin/sh", "sh", "-c", command, (char *)NULL);
        _exit(127);
    }
    close(fds[0]);
    FILE *f = *pid > 0 ? fdopen(fds[1], "w") : NULL;
    if (!f) {
        close(fds[1]);
        if (*pid > 0)
            waitpid(*pid, NULL, 0);
    }
    return f;
}

int video_open(video *v, const char *path, int width, int height, double fps)
{
    memset(v, 0, sizeof *v);
    if (video_check() != 0)
        return -1;
    char *part = part_file_name(path);
    char *quoted = part ? shell_quoted(part) : NULL;
    free(part);
    v->path = strdup(path);
    if (!quoted || !v->path) {
        free(quoted);
        free(v->path);
        return -1;
    }
    char command[8192];
    snprintf(command, sizeof command,
             "ffmpeg -hide_banner -loglevel error -nostdin -y -f rawvideo -pix_fmt %s -s %dx%d "
             "-r %g -i - -c:v %s -pix_fmt yuv420p -f mp4 %s",
             cairo_pixel_format(), width, height, fps, has_libx264() ? "libx264 -preset veryfast -crf 20" : "mpeg4 -q:v 3",
             quoted);
    free(quoted);
    struct sigaction ignore;
    memset(&ignore, 0, sizeof ignore);
    ignore.sa_handler = SIG_IGN;
    sigaction(SIGPIPE, &ignore, &previous_sigpipe);
    v->pipe = start_ffmpeg(command, &v->ffmpeg);
    if (!v->pipe) {
        fprintf(stderr, "openswarm-sim: cannot start ffmpeg for %s: %s\n", path, strerror(errno));
        sigaction(SIGPIPE, &previous_sigpipe, NULL);
        free(v->path);
        v->path = NULL;
        return -1;
    }
    v->width = width;
    v->height = height;
    return 0;
}

int video_frame(video *v, cairo_surface_t *frame)
{
    if (!v->pipe || v->failed)
        return -1;
    const unsigned char *data = cairo_image_surface_get_data(frame);
    const int stride = cairo_image_surface_get_stride(frame);
    for (int y = 0; y < v->height; y++) {
        if (fwrite(data + (size_t)y * (size_t)stride, 4, (size_t)v->width, v->pipe) !=
            (size_t)v->width) {
            fprintf(stderr, "openswarm-sim: ffmpeg stopped taking frames for %s (%s); its "
                            "message is above\n",
                    v->path, strerror(errno));
            v->failed = 1;
            return -1;
        }
    }
    v->frames++;
    return 0;
}

int video_close(video *v)
{
    if (!v->pipe)
        return 0;
    fclose(v->pipe); /* its end of file: ffmpeg finishes the file */
    int status = 0;
    pid_t done;
    while ((done = waitpid(v->ffmpeg, &status, 0)) < 0 && errno == EINTR)
        continue;
    sigaction(SIGPIPE, &previous_sigpipe, NULL);
    int rc = v->failed ? -1 : 0;
    if (done < 0) {
        fprintf(stderr, "openswarm-sim: ffmpeg writing %s: %s\n", v->path, strerror(errno));
        rc = -1;
    } else if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        if (WIFEXITED(status))
            fprintf(stderr, "openswarm-sim: ffmpeg failed (exit status %d) writing %s after %ld "
                            "frames; its message is above\n",
                    WEXITSTATUS(status), v->path, v->frames);
        else
            fprintf(stderr, "openswarm-sim: ffmpeg was killed writing %s\n", v->path);
        rc = -1;
    }
    if (part_file_finish(v->path, rc == 0) != 0)
        rc = -1;
    free(v->path);
    memset(v, 0, sizeof *v);
    return rc;
}
