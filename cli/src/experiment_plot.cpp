#include "experiment_plot.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

#include <cairo-svg.h>
#include <cairo.h>

namespace fs = std::filesystem;

namespace openswarm {

namespace {

constexpr double WIDTH = 960, HEIGHT = 440, PANEL_W = 380, PANEL_H = 300, TOP = 60, LEFT = 70;
// Colour-blind-safe pairs (Okabe and Ito): one per controller, in turn.
const double COLOURS[][3] = {{0.84, 0.37, 0.0}, {0.0, 0.45, 0.70}, {0.0, 0.62, 0.45},
                             {0.80, 0.47, 0.65}, {0.34, 0.71, 0.91}};

struct Panel {
    double x, y, w, h;    // where, in the picture
    double t_max, v_max;  // the axes' ends
    double px(double t) const { return x + w * t / t_max; }
    double py(double v) const { return y + h - h * v / v_max; }
};

void text(cairo_t *cr, double x, double y, const std::string &s, double size, bool centred = false) {
    cairo_set_font_size(cr, size);
    cairo_text_extents_t ext;
    cairo_text_extents(cr, s.c_str(), &ext);
    cairo_move_to(cr, centred ? x - ext.width / 2 : x, y);
    cairo_show_text(cr, s.c_str());
}

// A round step for about four ticks over range: 1, 2 or 5 times a power of 10.
double tick_step(double range) {
    double raw = range / 4, power = std::pow(10, std::floor(std::log10(raw)));
    for (double m : {1.0, 2.0, 5.0})
        if (m * power >= raw) return m * power;
    return 10 * power;
}

void axes(cairo_t *cr, const Panel &p, const std::string &title, bool percent) {
    cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
    cairo_set_line_width(cr, 1);
    cairo_rectangle(cr, p.x, p.y, p.w, p.h);
    cairo_stroke(cr);
    text(cr, p.x + p.w / 2, p.y - 12, title, 14, true);
    text(cr, p.x + p.w / 2, p.y + p.h + 36, "time (min)", 12, true);
    char label[32];
    double v_step = percent ? 0.25 : tick_step(p.v_max);
    for (double v = 0; v <= p.v_max + 1e-9; v += v_step) {
        std::snprintf(label, sizeof label, percent ? "%.0f%%" : "%.0f", percent ? v * 100 : v);
        text(cr, p.x - 44, p.py(v) + 4, label, 11);
    }
    double t_step = tick_step(p.t_max / 60) * 60;
    for (double t = 0; t <= p.t_max + 1e-9; t += t_step) {
        std::snprintf(label, sizeof label, "%g", t / 60);
        text(cr, p.px(t), p.y + p.h + 16, label, 11, true);
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
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
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
        const double *rgb = COLOURS[i % (sizeof COLOURS / sizeof COLOURS[0])];
        curve(cr, left, curves[i].time_s, curves[i].cluster_mean, curves[i].cluster_sd, rgb);
        curve(cr, right, curves[i].time_s, curves[i].compact_mean, curves[i].compact_sd, rgb);
        double x = LEFT + 260.0 * (double)i, y = HEIGHT - 12;
        cairo_set_source_rgb(cr, rgb[0], rgb[1], rgb[2]);
        cairo_set_line_width(cr, 3);
        cairo_move_to(cr, x, y - 4);
        cairo_line_to(cr, x + 24, y - 4);
        cairo_stroke(cr);
        cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
        text(cr, x + 30, y, curves[i].name + " (mean, band: +- 1 sd)", 12);
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
        text(cr, std::min(x, left.x + left.w - 8), left.y + 16, e.reference_label, 11, true);
    }
}

bool finish(cairo_surface_t *s, std::string &why) {
    cairo_surface_finish(s);
    bool ok = cairo_surface_status(s) == CAIRO_STATUS_SUCCESS;
    if (!ok) why = cairo_status_to_string(cairo_surface_status(s));
    cairo_surface_destroy(s);
    return ok;
}

bool render(cairo_surface_t *s, const Experiment &e, const std::vector<ControllerCurves> &curves) {
    cairo_t *cr = cairo_create(s);
    draw(cr, e, curves);
    bool ok = cairo_status(cr) == CAIRO_STATUS_SUCCESS;
    cairo_destroy(cr);
    return ok;
}

}  // namespace

bool write_experiment_plot(const Experiment &e, const std::vector<ControllerCurves> &curves,
                           const fs::path &dir, std::string &why) {
    cairo_surface_t *svg = cairo_svg_surface_create((dir / "results.svg").c_str(), WIDTH, HEIGHT);
    render(svg, e, curves);
    if (!finish(svg, why)) {
        why = (dir / "results.svg").string() + ": " + why;
        return false;
    }
    cairo_surface_t *png = cairo_image_surface_create(CAIRO_FORMAT_RGB24, (int)WIDTH, (int)HEIGHT);
    render(png, e, curves);
    cairo_status_t written = cairo_surface_write_to_png(png, (dir / "results.png").c_str());
    cairo_surface_destroy(png);
    if (written != CAIRO_STATUS_SUCCESS) {
        why = (dir / "results.png").string() + ": " + cairo_status_to_string(written);
        return false;
    }
    return true;
}

}  // namespace openswarm
