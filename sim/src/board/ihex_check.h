/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later (see sim/COPYING). */
/* An Intel HEX image (what KiloGUI uploads) checked whole before
 * libsimavr reads it: simavr 1.6's reader takes records without checking
 * their checksums, stops quietly at the first line it cannot read, and
 * places data wherever its address says. Plain C on a byte buffer, no
 * libsimavr. */
#ifndef OPENSWARM_SIM_IHEX_CHECK_H
#define OPENSWARM_SIM_IHEX_CHECK_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* 0 if every line is a well-formed record with a good checksum, the data
 * lies within the ATmega328P's 32 KB flash and an end-of-file record ends
 * it; -1 if not, with why (NUL-terminated, cut to why_size) saying which
 * line, what is wrong and, in parentheses, what to do. */
int ihex_check(const uint8_t *text, size_t size, char *why, size_t why_size);

#ifdef __cplusplus
}
#endif

#endif
