#pragma once

#include <string>
#include <vector>

namespace rad {

// One point of an error-against-time plot. Points of the same series share a colour, points of the same
// group (a scene, say) a marker shape; each has a legend entry.
struct PlotPoint {
    std::string series;
    std::string group;
    double seconds = 0.0;
    double error = 0.0;  // relative, 0.02 = 2 %
};

struct PlotLabels {
    std::string title;
    std::string x_axis = "time from the start, s";
    std::string y_axis = "error";
};

// An SVG scatter plot with logarithmic axes, decades gridded and labelled. Points with a non-positive or
// non-finite value cannot sit on a log axis and are left out.
std::string error_time_plot_svg(const std::vector<PlotPoint>& points, const PlotLabels& labels);

}  // namespace rad
