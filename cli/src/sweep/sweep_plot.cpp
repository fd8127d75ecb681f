#include "sweep_plot.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>

#include "../plot_parts.hpp"
#include "sweep_lines.hpp"
#include "sweep_stats.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace openswarm {

namespace {

constexpr double PANEL_W = 380, PANEL_H = 280, TOP = 56, LEFT = 80, GAP = 100, LINE = 16;
constexpr size_t LEGEND_MAX = 12;

// One metric at one point: mean and sd over the trials sample by sample,
// and the trials' values at the end.
struct PointCurve {
    std::vector<double> time_s, mean, sd;
    Summary end;
};

std::map<size_t, PointCurve> curves_of(const std::vector<SweepTrial> &trials, const std::string &metric) {
    std::map<size_t, std::vector<std::vector<std::pair<double, double>>>> runs;
    for (const SweepTrial &t : trials) {
        if (!t.failure.empty()) continue;
        for (const TrialSeries &series : t.series)
            if (series.metric == metric && !series.values.empty()) runs[t.point].push_back(series.values);
    }
    std::map<size_t, PointCurve> curves;
    for (const auto &[point, values] : runs) {
        PointCurve &c = curves[point];
        size_t n = values[0].size();
        for (const auto &v : values) n = std::min(n, v.size());
        std::vector<double> ends;
        for (const auto &v : values) ends.push_back(v.back().second);
        c.end = summarise(ends);
        for (size_t k = 0; k < n; k++) {
            std::vector<double> at;
            for (const auto &v : values) at.push_back(v[k].second);
            Summary m = summarise(at);
            c.time_s.push_back(values[0][k].first);
            c.mean.push_back(m.mean);
            c.sd.push_back(m.sd);
        }
    }
    return curves;
}

struct Panel {
    double x, y, w, h;
    double x0, x1, y0, y1; // the axes' ends
    double px(double v) const { return x + w * (v - x0) / (x1 - x0); }
    double py(double v) const { return y + h - h * (std::clamp(v, y0, y1) - y0) / (y1 - y0); }
};

// Round ends around lo..hi, 0 kept in for values that are never negative.
void round_range(double lo, double hi, double &from, double &to) {
    if (lo >= 0) lo = 0;
    if (!(hi > lo)) hi = lo + 1;
    double step = tick_step(hi - lo);
    from = std::floor(lo / step) * step;
    to = std::ceil(hi / step) * step;
}

void frame(cairo_t *cr, const Panel &p, const std::string &title, const std::string &x_label) {
    cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
    cairo_set_line_width(cr, 1);
    cairo_rectangle(cr, p.x, p.y, p.w, p.h);
    cairo_stroke(cr);
    plot_text(cr, p.x + p.w / 2, p.y - 12, title, 13, true);
    plot_text(cr, p.x + p.w / 2, p.y + p.h + 34, x_label, 12, true);
    char label[32];
    double step = tick_step(p.y1 - p.y0);
    for (double v = p.y0; v <= p.y1 + step * 1e-6; v += step) {
        std::snprintf(label, sizeof label, "%g", std::fabs(v) < step * 1e-6 ? 0.0 : v);
        plot_text(cr, p.x - 8 - 7 * (double)std::string(label).size(), p.py(v) + 4, label, 11);
    }
}

void x_ticks(cairo_t *cr, const Panel &p, double scale) {
    double step = tick_step((p.x1 - p.x0) / scale) * scale;
    char label[32];
    for (double v = std::ceil(p.x0 / step) * step; v <= p.x1 + step * 1e-6; v += step) {
        std::snprintf(label, sizeof label, "%g", std::fabs(v) < step * 1e-6 ? 0.0 : v / scale);
        plot_text(cr, p.px(v), p.y + p.h + 16, label, 11, true);
    }
}

void legend(cairo_t *cr, double x, double y, size_t entry, size_t count, const double *rgb, const std::string &text) {
    if (entry > LEGEND_MAX) return;
    y += LINE * (double)entry;
    if (entry == LEGEND_MAX) {
        cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
        plot_text(cr, x, y, "... and " + std::to_string(count - LEGEND_MAX) + " more", 11);
        return;
    }
    // Clipped to its panel's column: long labels ran into the next panel.
    constexpr size_t FITS = 72;
    plot_legend_entry(cr, x, y, rgb, 20, text.size() > FITS ? text.substr(0, FITS - 3) + "..." : text, 11);
}

void time_panel(cairo_t *cr, const Sweep &s, const std::map<size_t, PointCurve> &curves, Panel p) {
    p.x0 = 0;
    p.x1 = 1e-9;
    for (const auto &[point, c] : curves)
        if (!c.time_s.empty()) p.x1 = std::max(p.x1, c.time_s.back());
    bool minutes = p.x1 > 300;
    frame(cr, p, "over time (mean, band: +- 1 sd)", minutes ? "time (min)" : "time (s)");
    x_ticks(cr, p, minutes ? 60 : 1);
    size_t entry = 0;
    for (const auto &[point, c] : curves) {
        const double *rgb = plot_colour(point);
        for (size_t k = 0; k < c.time_s.size(); k++)
            (k ? cairo_line_to : cairo_move_to)(cr, p.px(c.time_s[k]), p.py(c.mean[k] + c.sd[k]));
        for (size_t k = c.time_s.size(); k-- > 0;) cairo_line_to(cr, p.px(c.time_s[k]), p.py(c.mean[k] - c.sd[k]));
        cairo_close_path(cr);
        cairo_set_source_rgba(cr, rgb[0], rgb[1], rgb[2], 0.12);
        cairo_fill(cr);
        for (size_t k = 0; k < c.time_s.size(); k++)
            (k ? cairo_line_to : cairo_move_to)(cr, p.px(c.time_s[k]), p.py(c.mean[k]));
        cairo_set_source_rgb(cr, rgb[0], rgb[1], rgb[2]);
        cairo_set_line_width(cr, 2);
        cairo_stroke(cr);
        legend(cr, p.x, p.y + p.h + 60, entry++, curves.size(), rgb,
               "point " + std::to_string(point + 1) + ": " + point_label(s, point));
    }
}

// Whether parameter k takes more than one value over the lines.
bool differs(const Sweep &s, const std::vector<std::vector<size_t>> &lines, size_t k) {
    for (const std::vector<size_t> &line : lines)
        if (s.points[line[0]][k] != s.points[lines[0][0]][k]) return true;
    return false;
}

// The end values against parameter `which`: numbers on a scale, anything
// else in the order the sweep lists it.
void parameter_panel(cairo_t *cr, const Sweep &s, const std::map<size_t, PointCurve> &curves, size_t which,
                     Panel p) {
    std::vector<json> values;
    for (const auto &point : s.points)
        if (std::find(values.begin(), values.end(), point[which]) == values.end()) values.push_back(point[which]);
    bool numeric = std::all_of(values.begin(), values.end(), [](const json &v) { return v.is_number(); });
    auto x_of = [&](const json &v) {
        return numeric ? v.get<double>() : (double)(std::find(values.begin(), values.end(), v) - values.begin());
    };
    double lo = x_of(values[0]), hi = lo;
    for (const json &v : values) lo = std::min(lo, x_of(v)), hi = std::max(hi, x_of(v));
    double pad = hi > lo ? (hi - lo) * 0.08 : 0.5;
    p.x0 = lo - pad;
    p.x1 = hi + pad;
    frame(cr, p, "at the end, by " + s.parameters[which].path + " (mean, 95% interval)", s.parameters[which].path);
    if (numeric) x_ticks(cr, p, 1);
    else
        for (const json &v : values)
            plot_text(cr, p.px(x_of(v)), p.y + p.h + 16, v.is_string() ? v.get<std::string>() : v.dump(), 11, true);
    // A line for each setting of the other parameters (sweep_lines.hpp).
    std::vector<std::vector<size_t>> lines = parameter_lines(s.points, which);
    size_t entry = 0;
    for (std::vector<size_t> &points : lines) {
        const double *rgb = plot_colour(entry);
        std::sort(points.begin(), points.end(),
                  [&](size_t a, size_t b) { return x_of(s.points[a][which]) < x_of(s.points[b][which]); });
        cairo_set_source_rgb(cr, rgb[0], rgb[1], rgb[2]);
        cairo_set_line_width(cr, 1.5);
        bool first = true;
        for (size_t point : points) {
            auto c = curves.find(point);
            if (c == curves.end() || c->second.end.n == 0) continue;
            double x = p.px(x_of(s.points[point][which]));
            (first ? cairo_move_to : cairo_line_to)(cr, x, p.py(c->second.end.mean));
            first = false;
        }
        cairo_stroke(cr);
        for (size_t point : points) {
            auto c = curves.find(point);
            if (c == curves.end() || c->second.end.n == 0) continue;
            double x = p.px(x_of(s.points[point][which]));
            cairo_move_to(cr, x, p.py(c->second.end.low));
            cairo_line_to(cr, x, p.py(c->second.end.high));
            cairo_stroke(cr);
            cairo_arc(cr, x, p.py(c->second.end.mean), 3.5, 0, 2 * M_PI);
            cairo_fill(cr);
        }
        std::string label; // the other parameters that tell this line from the others
        for (size_t k = 0; k < s.parameters.size(); k++)
            if (k != which && differs(s, lines, k))
                label += (label.empty() ? "" : ", ") + s.parameters[k].path + "=" + s.points[points[0]][k].dump();
        legend(cr, p.x, p.y + p.h + 60, entry++, lines.size(), rgb, label.empty() ? "all points" : label);
    }
}

// The safe part of a metric's name for a file (names are letters, digits, _ . -).
std::string file_stem(const std::string &metric) {
    std::string stem;
    for (char c : metric) stem += std::isalnum((unsigned char)c) || c == '_' || c == '-' || c == '.' ? c : '_';
    return stem;
}

}  // namespace

bool write_sweep_plots(const Sweep &s, const std::vector<SweepTrial> &trials, const fs::path &out,
                       std::vector<fs::path> &written, std::string &why) {
    std::vector<std::string> metrics;
    for (const SweepTrial &t : trials) {
        if (!t.failure.empty()) continue;
        for (const TrialSeries &series : t.series)
            if (std::find(metrics.begin(), metrics.end(), series.metric) == metrics.end())
                metrics.push_back(series.metric);
    }
    std::error_code ec;
    fs::create_directories(out / "plots", ec);
    if (ec) {
        why = "cannot create " + (out / "plots").string() + ": " + ec.message();
        return false;
    }
    size_t panels = 1 + s.parameters.size(), rows = std::min(LEGEND_MAX + 1, s.points.size());
    double width = LEFT + (double)panels * (PANEL_W + GAP), height = TOP + PANEL_H + 70 + LINE * (double)rows;
    for (const std::string &metric : metrics) {
        auto curves = curves_of(trials, metric);
        double lo = INFINITY, hi = -INFINITY;
        for (const auto &[point, c] : curves) {
            for (size_t k = 0; k < c.mean.size(); k++)
                lo = std::min(lo, c.mean[k] - c.sd[k]), hi = std::max(hi, c.mean[k] + c.sd[k]);
            lo = std::min(lo, c.end.low);
            hi = std::max(hi, c.end.high);
        }
        Panel p{LEFT, TOP, PANEL_W, PANEL_H, 0, 1, 0, 1};
        round_range(lo, hi, p.y0, p.y1);
        auto draw = [&](cairo_t *cr) {
            cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
            plot_text(cr, LEFT, 24, metric + " - " + s.file.filename().string() + ", " + std::to_string(s.trials) +
                                        " trial" + (s.trials == 1 ? "" : "s") + " a point", 14);
            time_panel(cr, s, curves, p);
            for (size_t k = 0; k < s.parameters.size(); k++) {
                Panel q = p;
                q.x += (double)(k + 1) * (PANEL_W + GAP);
                parameter_panel(cr, s, curves, k, q);
            }
        };
        if (!write_plot(out / "plots", file_stem(metric), width, height, draw, why)) return false;
        written.push_back(out / "plots" / (file_stem(metric) + ".png"));
    }
    return true;
}

}  // namespace openswarm
