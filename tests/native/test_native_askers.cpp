// The robots asking to transmit, answered in the order they asked
// (sim/src/native/native_askers.c): by nominal cycle, then by index,
// whatever order the threads noted them in, and with askers added while
// the earlier ones are answered (a robot that asks again).
#include <gtest/gtest.h>

#include <vector>

extern "C" {
#include "native/native_askers.h"
}

TEST(NativeAskers, FirstAskedFirstThenByIndex) {
    native_askers_push(300, 7);
    native_askers_push(100, 9);
    native_askers_push(300, 2);
    native_askers_push(100, 4);
    native_askers_push(200, 1);
    std::vector<int> order;
    for (int i; (i = native_askers_pop()) >= 0;) order.push_back(i);
    EXPECT_EQ(order, (std::vector<int>{4, 9, 1, 2, 7}));
    EXPECT_EQ(native_askers_pop(), -1);
}

TEST(NativeAskers, AskingAgainWhileAnswered) {
    // Many askers (the heap grows past its first room), pushed from the
    // latest down; each answered robot below 50 asks again later.
    for (int i = 0; i < 500; i++) native_askers_push((uint64_t)(1000 - i), i);
    std::vector<int> order;
    for (int i; (i = native_askers_pop()) >= 0;) {
        order.push_back(i);
        if (i < 50 && order.size() < 1000) native_askers_push(5000 + (uint64_t)i, 1000 + i);
    }
    ASSERT_EQ(order.size(), 550u);
    for (int k = 0; k < 500; k++) EXPECT_EQ(order[(size_t)k], 499 - k);
    for (int k = 0; k < 50; k++) EXPECT_EQ(order[500 + (size_t)k], 1000 + k);
}
