// The figures library's own header (animpak/report.hpp is its public one): line plots as inline SVG, drawn
// by animpak's own code (no plotting library), for the report page (report_page.cpp), the sweep's page
// (sweep_page.cpp) and the trajectory figure (trajectory_figure.cpp). Each plot is one <svg class="plot">
// whose look is kPlotStyle's CSS.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace animpak {

/// One line of a plot: its points (a null y breaks the line), its colour and its role.
struct Series {
  std::string name;
  std::vector<double> x;
  std::vector<std::optional<double>> y;
  std::string color;
  std::string role = "main";  ///< main (the plot's own figure), extra (drawn thin), reference (dashed level)
};

/// The plot's id, titles, x range, and whether its x axis is the frame time.
struct PlotSpec {
  std::string id, title, x_label, y_label;
  double x_min = 0.0, x_max = 1.0;
  bool time_axis = true;                               ///< x is the frame time: the scrubber's cursor moves over it
  std::optional<double> y_floor;                       ///< the y axis starts here at most (0 for shares)
  std::string empty_note = "no values in stats.json";  ///< written across a plot without any value
  bool log_x = false;  ///< x on a logarithmic axis (x_min > 0), ticked at the powers of ten: a sweep's stiffness
};

/// A line plot 440 × 230 px: axes with round ticks, one polyline per run of values, the main series' points
/// as dots (up to 200 of them), a legend; with `time_axis`, a hidden cursor line a page's script moves to a
/// frame time (data-x0, data-x1 give the axis' pixel range).
std::string plot(const PlotSpec& spec, const std::vector<Series>& series);

/// The CSS that draws plot()'s SVG: in the report page's <style>, or inside a standalone SVG's.
extern const char* const kPlotStyle;

/// A round step for about `count` ticks over `range`: 1, 2 or 5 times a power of ten.
double tick_step(double range, int count);

}  // namespace animpak
