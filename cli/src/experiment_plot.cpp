#include "experiment_plot.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

#include "plot_parts.hpp"

namespace fs = std::filesystem;

namespace openswarm {

namespace {

constexpr double WIDTH = 960, HEIGHT = 440, PANEL_W = 380, PANEL_H = 300, TOP = 60, LEFT = 70;

struct Panel {
    double x, y, w, h;    // where, in the picture
    double t_max, v_max;  // the axes' ends
    double px(double t) const { return x + w * t / t_max; }
    double py(double v) const { return y + h - h * v / v_max; }
};

void axes(cairo_t *cr, const Panel &p, const std::string &title, bool percent) {
    cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
    cairo_set_line_width(cr, 1);
    cairo_rectangle(cr, p.x, p.y, p.w, p.h);
    cairo_stroke(cr);
    plot_text(cr, p.x + p.w / 2, p.y - 12, title, 14, true);
    plot_text(cr, p.x + p.w / 2, p.y + p.h + 36, "time (min)", 12, true);
    char label[32];
    double v_step = percent ? 0.25 : tick_step(p.v_max);
    for (double v = 0; v <= p.v_max + 1e-9; v += v_step) {
        std::snprintf(label, sizeof label, percent ? "%.0f%%" : "%.0f", percent ? v * 100 : v);
        plot_text(cr, p.x - 44, p.py(v) + 4, label, 11);
    }
    double t_step = tick_step(p.t_max / 60) * 60;
    for (double t = 0; t <= p.t_max + 1e-9; t += t_step) {
        std::snprintf(label, sizeof label, "%g", t / 60);
        plot_text(cr, p.px(t), p.y + p.h + 16, label, 11, true);
    }
}

// A mean curve and its band of one standard deviation.
void curve(cairo_t *cr, const Panel &p, const std::vector<double> &t, const std::vector<double> &mean,
           const std::vector<double> &sd, const double *rgb) {
    if (t.empty()) return;
    auto clamp = [&](double v) { return std::clamp(v, 0.0, p.v_max); };
    for (size_t k = 0; k < t.size(); k++)
        (k ? cairo_line_to : cairo_move_to)(cr, p.px(t[k]), p.py(clamp(mean[k] + sd[k])));
    for (size_t k = t.size(); k-- > 0;) cairo_line_to(cr, p.px(t[k]), p.py(clamp(mean[k] - sd[k])));
    cairo_close_path(cr);
    cairo_set_source_rgba(cr, rgb[0], rgb[1], rgb[2], 0.18);
    cairo_fill(cr);
    for (size_t k = 0; k < t.size(); k++) (k ? cairo_line_to : cairo_move_to)(cr, p.px(t[k]), p.py(clamp(mean[k])));
    cairo_set_source_rgb(cr, rgb[0], rgb[1], rgb[2]);
    cairo_set_line_width(cr, 2);
    cairo_stroke(cr);
}

void draw(cairo_t *cr, const Experiment &e, const std::vector<ControllerCurves> &curves) {
    double compact_max = 1;
    for (const auto &c : curves)
        for (size_t k = 0; k < c.compact_mean.size(); k++)
            compact_max = std::max(compact_max, c.compact_mean[k] + c.compact_sd[k]);
    compact_max = std::ceil(compact_max / tick_step(compact_max)) * tick_step(compact_max); // a round top
    Panel left{LEFT, TOP, PANEL_W, PANEL_H, e.duration_s, 1.0};
    Panel right{LEFT + PANEL_W + 80, TOP, PANEL_W, PANEL_H, e.duration_s, compact_max};
    axes(cr, left, "objects in the largest cluster", true);
    axes(cr, right, "compactness, eq. (2) (lower: tighter)", false);
    for (size_t i = 0; i < curves.size(); i++) {
        const double *rgb = plot_colour(i);
        curve(cr, left, curves[i].time_s, curves[i].cluster_mean, curves[i].cluster_sd, rgb);
        curve(cr, right, curves[i].time_s, curves[i].compact_mean, curves[i].compact_sd, rgb);
        double x = LEFT + 260.0 * (double)i, y = HEIGHT - 12;
        plot_legend_entry(cr, x, y, rgb, 24, curves[i].name + " (mean, band: +- 1 sd)", 12);
    }
    if (e.reference_fraction >= 0) {
        double x = left.px(e.reference_time_s), y = left.py(e.reference_fraction);
        cairo_set_source_rgb(cr, 0, 0, 0);
        cairo_arc(cr, x, y, 5, 0, 2 * M_PI);
        cairo_fill(cr);
        // The label under the panel's title, out of the curves' way.
        cairo_move_to(cr, x, y - 6);
        cairo_line_to(cr, x, left.y + 22);
        cairo_set_line_width(cr, 0.8);
        cairo_stroke(cr);
        plot_text(cr, std::min(x, left.x + left.w - 8), left.y + 16, e.reference_label, 11, true);
    }
}

}  // namespace

bool write_experiment_plot(const Experiment &e, const std::vector<ControllerCurves> &curves,
                           const fs::path &dir, std::string &why) {
    return write_plot(dir, "results", WIDTH, HEIGHT, [&](cairo_t *cr) { draw(cr, e, curves); }, why);
}

}  // namespace openswarm
