// An experiment's statistics (experiment_curves.hpp).
#include "experiment_curves.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "duration_text.hpp"

namespace openswarm {

namespace {

// The value of a curve at the sample nearest time t.
size_t nearest(const ControllerCurves &c, double t) {
    size_t best = 0;
    for (size_t k = 0; k < c.time_s.size(); k++)
        if (std::fabs(c.time_s[k] - t) < std::fabs(c.time_s[best] - t)) best = k;
    return best;
}

}  // namespace

ControllerCurves controller_curves(const std::string &name, const std::vector<const std::vector<Sample> *> &trials) {
    ControllerCurves cc{name, {}, {}, {}, {}, {}};
    size_t n = trials.empty() ? 0 : trials[0]->size();
    for (const auto *t : trials) n = std::min(n, t->size());
    for (size_t k = 0; k < n; k++) {
        auto stats = [&](double Sample::*field, std::vector<double> &mean, std::vector<double> &sd) {
            double sum = 0, squares = 0;
            for (const auto *t : trials) sum += (*t)[k].*field;
            double m = sum / (double)trials.size();
            for (const auto *t : trials) squares += ((*t)[k].*field - m) * ((*t)[k].*field - m);
            mean.push_back(m);
            sd.push_back(trials.size() > 1 ? std::sqrt(squares / (double)(trials.size() - 1)) : 0.0);
        };
        cc.time_s.push_back((*trials[0])[k].time_s);
        stats(&Sample::cluster, cc.cluster_mean, cc.cluster_sd);
        stats(&Sample::compactness, cc.compact_mean, cc.compact_sd);
    }
    return cc;
}

void print_experiment_table(const Experiment &e, const std::vector<ControllerCurves> &curves) {
    double mid = e.reference_fraction >= 0 ? e.reference_time_s : e.duration_s / 2;
    std::printf("\n%-16s %22s %22s %18s\n", "controller",
                ("largest cluster " + duration_text(mid)).c_str(),
                ("largest cluster " + duration_text(e.duration_s)).c_str(), "compactness end");
    for (const auto &c : curves) {
        if (c.time_s.empty()) {
            std::printf("%-16s %22s\n", c.name.c_str(), "no trial ran");
            continue;
        }
        size_t m = nearest(c, mid), end = c.time_s.size() - 1;
        char a[40], b[40], d[40];
        std::snprintf(a, sizeof a, "%.1f%% +- %.1f", c.cluster_mean[m] * 100, c.cluster_sd[m] * 100);
        std::snprintf(b, sizeof b, "%.1f%% +- %.1f", c.cluster_mean[end] * 100, c.cluster_sd[end] * 100);
        std::snprintf(d, sizeof d, "%.1f +- %.1f", c.compact_mean[end], c.compact_sd[end]);
        std::printf("%-16s %22s %22s %18s\n", c.name.c_str(), a, b, d);
    }
    if (e.reference_fraction >= 0) {
        char r[40];
        std::snprintf(r, sizeof r, "%.1f%%", e.reference_fraction * 100);
        std::printf("%-16s %22s   (%s)\n", "reference", r, e.reference_label.c_str());
    }
}

}  // namespace openswarm
