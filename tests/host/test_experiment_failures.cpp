// Failure reasons between MPI ranks (cli/src/experiment_failures.cpp): a
// reason is the simulator's output, newlines and tabs included; one such
// reason from rank 1 crashed rank 0 (std::stoul on a line of it, issue 30).
#include <gtest/gtest.h>

#include "../../cli/src/experiment_failures.hpp"

using openswarm::TrialOutcome;

namespace {

std::vector<TrialOutcome> ran_here(std::vector<std::string> failures) {
    std::vector<TrialOutcome> outcomes(failures.size());
    for (size_t k = 0; k < failures.size(); k++) {
        outcomes[k].failure = failures[k];
        outcomes[k].here = true;
    }
    return outcomes;
}

TEST(ExperimentFailures, ReasonsWithNewlinesAndTabsArriveWhole) {
    const std::string simulator =
        "the firmware crashed (above):\nepuck world link: robot 1's controller\tanswered 0x1\n"
        "7\tlooks like a record\n\n";
    auto sent = ran_here({"", simulator, "", "tab\tat\tend\t", "\n"});
    std::vector<TrialOutcome> received(sent.size());
    std::string why;
    ASSERT_TRUE(openswarm::decode_failures(openswarm::encode_failures(sent), received, why)) << why;
    for (size_t k = 0; k < sent.size(); k++) EXPECT_EQ(sent[k].failure, received[k].failure) << "trial " << k;
}

TEST(ExperimentFailures, OnlyTheTrialsRunHereAreSent) {
    auto sent = ran_here({"mine", "not mine"});
    sent[1].here = false;
    std::vector<TrialOutcome> received(2);
    received[1].failure = "rank 0's own";
    std::string why;
    ASSERT_TRUE(openswarm::decode_failures(openswarm::encode_failures(sent), received, why)) << why;
    EXPECT_EQ("mine", received[0].failure);
    EXPECT_EQ("rank 0's own", received[1].failure);
}

TEST(ExperimentFailures, ATextItDidNotWriteIsRefusedNotACrash) {
    std::vector<TrialOutcome> received(2);
    std::string why;
    for (const std::string bad : {"x", "9 1\na", "1 5\nab", "1\tno length\n", "18446744073709551616 1\na"}) {
        why.clear();
        EXPECT_FALSE(openswarm::decode_failures(bad, received, why)) << bad;
        EXPECT_FALSE(why.empty()) << bad;
    }
}

}  // namespace
