/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* A native robot's RAM image copied and summed in one pass
 * (native_image_copy.h). */
#include "native/native_image_copy.h"

#include <string.h>

static uint64_t swap_halves(uint64_t x) { return x << 32 | x >> 32; }

/* Four words side by side: the compiler's vectors, two SSE2 registers on
 * any x86-64, one AVX2 register where the CPU has it (the clone below). */
typedef uint64_t four_words __attribute__((vector_size(32)));

/* It runs twice per switch of robots, about a hundred times a robot a
 * simulated second in a packed swarm: one pass that stores each 64 bytes as it adds them, in eight
 * lanes of word sums and sums of those (Fletcher's pair: a changed word
 * changes the first, words moved or swapped the second), only additions,
 * so no lane waits on a multiply (a multiply a word cost 15% of a
 * thousand robots' run; a copy, then a pass of scalar sums, 15% of the
 * robots' thread). */
__attribute__((target_clones("avx2", "default")))
static uint64_t copy_summed(uint8_t *restrict dst, const uint8_t *restrict src, size_t n) {
    four_words a0 = {0}, a1 = {0}, b0 = {0}, b1 = {0};
    size_t whole = n / 64 * 64;
    for (size_t i = 0; i < whole; i += 64) {
        four_words w0, w1;
        memcpy(&w0, src + i, sizeof w0);
        memcpy(&w1, src + i + 32, sizeof w1);
        memcpy(dst + i, &w0, sizeof w0);
        memcpy(dst + i + 32, &w1, sizeof w1);
        b0 += a0 += w0;
        b1 += a1 += w1;
    }
    four_words last[2] = {{0}, {0}}; /* the last bytes, zero-padded */
    memcpy(last, src + whole, n - whole);
    memcpy(dst + whole, last, n - whole);
    b0 += a0 += last[0];
    b1 += a1 += last[1];
    static const uint64_t mix[4] = {0x9E3779B97F4A7C15ull, 0xC2B2AE3D27D4EB4Full, 0x165667B19E3779F9ull,
                                    0x27D4EB2F165667C5ull};
    uint64_t h = 0;
    for (int lane = 0; lane < 4; lane++) {
        h = (h ^ a0[lane] ^ swap_halves(b0[lane])) * mix[lane];
        h = (h ^ a1[lane] ^ swap_halves(b1[lane])) * mix[lane];
    }
    return h ^ (h >> 29);
}

/* The clones' choice stays inside this file: clang dispatches a
 * target_clones function only where it is called. */
uint64_t native_image_copy_summed(uint8_t *dst, const uint8_t *src, size_t n) { return copy_summed(dst, src, n); }
