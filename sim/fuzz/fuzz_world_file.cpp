// Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links the simulator's world reader.
// world.json, any bytes: the reader accepts or refuses with a message, and
// never crashes, leaks or reads out of bounds.
#include "fuzz_input_file.hpp"
#include "world/world_spec.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    auto path = write_input("world.json", data, size);
    world_spec w{};
    if (world_spec_load(path.c_str(), &w) == 0) world_spec_free(&w);
    return 0;
}
