// The robots' IR at one sample (ir.csv's counts since the run began), as
// means over robots: what the built-in metrics ir_sent, ir_received,
// ir_lost and ir_lost_channel measure (builtin_metrics.cpp).
#pragma once

#include <vector>

#include "run_snapshots.hpp"

namespace openswarm {

enum class IrCount {
    sent,         // frames its firmware sent
    received,     // frames its firmware received (delivered to the app)
    lost,         // frames robots in range sent that it did not receive: heard + lost_channel - received
    lost_channel, // frames robots in range sent that the channel lost on the way
};

// The mean over robots of one count; the firmware's counts (sent,
// received, lost) over the robots whose firmware keeps counters. NaN when
// no robot has the count.
double mean_ir_count(const std::vector<IrSample> &ir, IrCount what);

}  // namespace openswarm
