/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* Box2D's profiling clock, stopped. Box2D 2.4.1 (Debian's libbox2d) times
 * every step for its b2Profile, which nothing here reads: a b2Timer made,
 * reset or read five times per island per step, each a gettimeofday. A
 * spread-out swarm is an island per robot: at a thousand robots that is
 * half a million clock reads per simulated second, 4% of a native run
 * (perf, docs/benchmarks.md). The library calls its timer through its PLT,
 * so these definitions in the simulator replace its own; the physics
 * never reads a timer, so its results are the same to the bit. */
#include <box2d/b2_timer.h>

b2Timer::b2Timer() : m_start_sec(0), m_start_usec(0) {}

void b2Timer::Reset() {}

float b2Timer::GetMilliseconds() const { return 0.0f; }
