/* printf on an e-puck2 board's console: newlib's stdout ends in _write,
 * which here is the board's console (USART3 on the robot, USART1 under
 * QEMU). The system calls newlib needs besides are the smallest honest
 * ones: no files, and no open-ended heap. Newlib-nano's stdio allocates
 * its stream records on first use (__sinit, 436 bytes for four), so
 * _sbrk hands out a fixed arena, sized for them and too small for a
 * stream's 1 KB buffer: stdout then stays unbuffered (each printf goes
 * out at once, as the Kilobot's), and a malloc beyond the arena fails
 * instead of growing into the stacks. */
#include <errno.h>
#include <stdio.h>
#include <sys/stat.h>

#include "openswarm/cortex_m4.h"
#include "openswarm/robot.h"

#define ARENA_BYTES 512u

static unsigned char arena[ARENA_BYTES] __attribute__((aligned(8)));
static unsigned arena_used;

/* Linking this file is what routes printf to the console (_write below);
 * nothing to set up at run time. */
void epuck_console_init(void) {}

/* Kept through link-time optimisation, which sees no caller: newlib's
 * (not LTO-compiled) calls them. */

int _write(int fd, const char *bytes, int length);
int _read(int fd, char *bytes, int length);
int _close(int fd);
int _fstat(int fd, struct stat *st);
int _isatty(int fd);
int _lseek(int fd, int offset, int whence);
void *_sbrk(int increment);

__attribute__((used)) int _write(int fd, const char *bytes, int length) {
    if (fd != 1 && fd != 2) {
        errno = EBADF;
        return -1;
    }
    board_console_write(bytes, (uint32_t)length);
    return length;
}

__attribute__((used)) int _read(int fd, char *bytes, int length) {
    (void)fd, (void)bytes, (void)length;
    return 0; /* nothing to read: end of file */
}

__attribute__((used)) int _close(int fd) {
    (void)fd;
    errno = EBADF;
    return -1;
}

__attribute__((used)) int _fstat(int fd, struct stat *st) {
    (void)fd;
    st->st_mode = S_IFCHR;
    return 0;
}

__attribute__((used)) int _isatty(int fd) { return fd <= 2; }

__attribute__((used)) int _lseek(int fd, int offset, int whence) {
    (void)fd, (void)offset, (void)whence;
    errno = ESPIPE;
    return -1;
}

__attribute__((used)) void *_sbrk(int increment) {
    if (increment < 0 || (unsigned)increment > ARENA_BYTES - arena_used) {
        errno = ENOMEM;
        return (void *)-1;
    }
    void *start = &arena[arena_used];
    arena_used += (unsigned)increment;
    return start;
}
