// What the tool's plots share (drawn with Cairo): colours, text, round
// ticks, and writing one drawing as PNG and SVG.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>

#include <cairo.h>

namespace openswarm {

// Colour-blind-safe (Okabe and Ito), one per series in turn.
const double *plot_colour(size_t series);

void plot_text(cairo_t *cr, double x, double y, const std::string &s, double size, bool centred = false);

// A legend's entry: a line of the series' colour, length long, and its label.
void plot_legend_entry(cairo_t *cr, double x, double y, const double *rgb, double length, const std::string &label,
                       double size);

// A round step for about four ticks over range: 1, 2 or 5 times a power of 10.
double tick_step(double range);

// Draws the picture into dir/stem.svg and dir/stem.png, width x height;
// false with why (naming the file) when one cannot be written.
bool write_plot(const std::filesystem::path &dir, const std::string &stem, double width, double height,
                const std::function<void(cairo_t *)> &draw, std::string &why);

}  // namespace openswarm
