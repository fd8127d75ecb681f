#include "plot_parts.hpp"

#include <cmath>

#include <cairo-svg.h>

namespace fs = std::filesystem;

namespace openswarm {

namespace {

bool render(cairo_surface_t *s, const std::function<void(cairo_t *)> &draw) {
    cairo_t *cr = cairo_create(s);
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    draw(cr);
    bool ok = cairo_status(cr) == CAIRO_STATUS_SUCCESS;
    cairo_destroy(cr);
    return ok;
}

}  // namespace

const double *plot_colour(size_t series) {
    static const double colours[][3] = {{0.84, 0.37, 0.0}, {0.0, 0.45, 0.70}, {0.0, 0.62, 0.45},
                                        {0.80, 0.47, 0.65}, {0.34, 0.71, 0.91}, {0.90, 0.62, 0.0},
                                        {0.94, 0.89, 0.26}, {0.0, 0.0, 0.0}};
    return colours[series % (sizeof colours / sizeof colours[0])];
}

void plot_text(cairo_t *cr, double x, double y, const std::string &s, double size, bool centred) {
    cairo_set_font_size(cr, size);
    cairo_text_extents_t ext;
    cairo_text_extents(cr, s.c_str(), &ext);
    cairo_move_to(cr, centred ? x - ext.width / 2 : x, y);
    cairo_show_text(cr, s.c_str());
}

void plot_legend_entry(cairo_t *cr, double x, double y, const double *rgb, double length, const std::string &label,
                       double size) {
    cairo_set_source_rgb(cr, rgb[0], rgb[1], rgb[2]);
    cairo_set_line_width(cr, 3);
    cairo_move_to(cr, x, y - 4);
    cairo_line_to(cr, x + length, y - 4);
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    plot_text(cr, x + length + 6, y, label, size);
}

double tick_step(double range) {
    double raw = range / 4, power = std::pow(10, std::floor(std::log10(raw)));
    for (double m : {1.0, 2.0, 5.0})
        if (m * power >= raw) return m * power;
    return 10 * power;
}

bool write_plot(const fs::path &dir, const std::string &stem, double width, double height,
                const std::function<void(cairo_t *)> &draw, std::string &why) {
    fs::path svg_file = dir / (stem + ".svg"), png_file = dir / (stem + ".png");
    cairo_surface_t *svg = cairo_svg_surface_create(svg_file.c_str(), width, height);
    bool drawn = render(svg, draw);
    cairo_surface_finish(svg);
    cairo_status_t status = cairo_surface_status(svg);
    cairo_surface_destroy(svg);
    if (!drawn || status != CAIRO_STATUS_SUCCESS) {
        why = svg_file.string() + ": " + cairo_status_to_string(status);
        return false;
    }
    cairo_surface_t *png = cairo_image_surface_create(CAIRO_FORMAT_RGB24, (int)width, (int)height);
    render(png, draw);
    status = cairo_surface_write_to_png(png, png_file.c_str());
    cairo_surface_destroy(png);
    if (status != CAIRO_STATUS_SUCCESS) {
        why = png_file.string() + ": " + cairo_status_to_string(status);
        return false;
    }
    return true;
}

}  // namespace openswarm
