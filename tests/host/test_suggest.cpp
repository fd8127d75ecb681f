// The did-you-mean of the tool's errors (cli/src/suggest.cpp): the nearest
// valid word, a swap of two neighbouring letters counting as one typo.
#include <gtest/gtest.h>

#include "../../cli/src/suggest.hpp"

namespace {

const std::vector<std::string> types = {"none", "int8", "uint8", "int16", "uint16", "int32", "uint32"};

// Issue 31: "unit16" suggested "int16" (two edits from uint16 without
// transpositions, and int16 came first).
TEST(Suggest, SwappedLettersAreOneTypo) {
    EXPECT_EQ("uint16", openswarm::nearest("unit16", types));
    EXPECT_EQ("priority", openswarm::nearest("prioirty", {"round-robin", "priority"}));
}

TEST(Suggest, OtherTyposStillFindTheirWord) {
    EXPECT_EQ("int16", openswarm::nearest("int61", types));
    EXPECT_EQ("uint8", openswarm::nearest("uint", types));
    EXPECT_EQ("", openswarm::nearest("xyzzyxyzzy", types));
    EXPECT_EQ(" (did you mean \"kernel\"?)", openswarm::did_you_mean("kernal", {"name", "kernel"}, '"'));
}

}  // namespace
