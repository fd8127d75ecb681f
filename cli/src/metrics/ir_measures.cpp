#include "ir_measures.hpp"

#include <cmath>

namespace openswarm {

namespace {

double count_of(const IrSample &r, IrCount what) {
    switch (what) {
    case IrCount::sent: return r.sent;
    case IrCount::received: return r.received;
    case IrCount::lost: return r.heard + r.lost_channel - r.received; // NaN with received
    case IrCount::lost_channel: return r.lost_channel;
    }
    return NAN;
}

}  // namespace

double mean_ir_count(const std::vector<IrSample> &ir, IrCount what) {
    double sum = 0;
    int n = 0;
    for (const auto &r : ir) {
        double v = count_of(r, what);
        if (std::isnan(v)) continue; // a firmware without counters
        sum += v;
        n++;
    }
    return n == 0 ? NAN : sum / n;
}

}  // namespace openswarm
