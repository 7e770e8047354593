#include "bench/error_time_plot.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>

namespace rad {

namespace {

constexpr double kWidth = 760, kHeight = 480;
constexpr double kLeft = 70, kRight = 200, kTop = 40, kBottom = 50;  // margins; the legend sits right
constexpr std::array<const char*, 8> kColours = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e",
                                                 "#9467bd", "#8c564b", "#e377c2", "#17becf"};

// Whole decades around [low, high], so every point lies inside a gridded range.
struct LogAxis {
    double low_decade = 0, high_decade = 1;
    double to_unit(double value) const {
        return (std::log10(value) - low_decade) / (high_decade - low_decade);
    }
};

LogAxis axis_around(double low, double high) {
    LogAxis axis{std::floor(std::log10(low)), std::ceil(std::log10(high))};
    if (axis.high_decade <= axis.low_decade) axis.high_decade = axis.low_decade + 1;
    return axis;
}

std::string format(const char* pattern, double a, double b = 0, double c = 0) {
    char text[160];
    std::snprintf(text, sizeof text, pattern, a, b, c);
    return text;
}

std::string escape(const std::string& text) {
    std::string out;
    for (char c : text) {
        if (c == '<')
            out += "&lt;";
        else if (c == '>')
            out += "&gt;";
        else if (c == '&')
            out += "&amp;";
        else
            out += c;
    }
    return out;
}

std::string decade_label(double decade, bool percent) {
    const double value = std::pow(10.0, decade) * (percent ? 100.0 : 1.0);
    return format("%g", value) + (percent ? " %" : "");
}

std::string grid(const LogAxis& x, const LogAxis& y) {
    const double plot_w = kWidth - kLeft - kRight, plot_h = kHeight - kTop - kBottom;
    std::string svg;
    for (double d = x.low_decade; d <= x.high_decade; ++d) {
        const double px = kLeft + x.to_unit(std::pow(10.0, d)) * plot_w;
        svg += format("<line x1='%.1f' y1='%.1f' x2='%.1f' ", px, kTop, px) +
               format("y2='%.1f' stroke='#ccc'/>\n", kTop + plot_h);
        svg += format("<text x='%.1f' y='%.1f' text-anchor='middle'>", px, kTop + plot_h + 18) +
               decade_label(d, false) + "</text>\n";
    }
    for (double d = y.low_decade; d <= y.high_decade; ++d) {
        const double py = kTop + (1.0 - y.to_unit(std::pow(10.0, d))) * plot_h;
        svg += format("<line x1='%.1f' y1='%.1f' x2='%.1f' ", kLeft, py, kLeft + plot_w) +
               format("y2='%.1f' stroke='#ccc'/>\n", py);
        svg += format("<text x='%.1f' y='%.1f' text-anchor='end'>", kLeft - 6, py + 4) +
               decade_label(d, true) + "</text>\n";
    }
    return svg;
}

// A circle, square or triangle at (x, y), with a tooltip.
std::string marker(std::size_t shape, double x, double y, const std::string& colour,
                   const std::string& tooltip) {
    const std::string style = "fill='" + colour + "' fill-opacity='0.8'><title>" + tooltip + "</title>";
    if (shape == 1)
        return format("<rect x='%.1f' y='%.1f' width='8' height='8' ", x - 4, y - 4) + style + "</rect>\n";
    if (shape == 2) {
        return format("<polygon points='%.1f,%.1f ", x, y - 5) + format("%.1f,%.1f ", x - 5, y + 4) +
               format("%.1f,%.1f' ", x + 5, y + 4) + style + "</polygon>\n";
    }
    return format("<circle cx='%.1f' cy='%.1f' r='4' ", x, y) + style + "</circle>\n";
}

}  // namespace

std::string error_time_plot_svg(const std::vector<PlotPoint>& points, const PlotLabels& labels) {
    std::vector<PlotPoint> shown;
    for (const PlotPoint& p : points) {
        if (std::isfinite(p.seconds) && std::isfinite(p.error) && p.seconds > 0 && p.error > 0)
            shown.push_back(p);
    }
    double x_low = 1, x_high = 10, y_low = 0.01, y_high = 0.1;
    if (!shown.empty()) {
        const auto [xmin, xmax] = std::minmax_element(shown.begin(), shown.end(),
                                                      [](auto& a, auto& b) { return a.seconds < b.seconds; });
        const auto [ymin, ymax] = std::minmax_element(shown.begin(), shown.end(),
                                                      [](auto& a, auto& b) { return a.error < b.error; });
        x_low = xmin->seconds, x_high = xmax->seconds, y_low = ymin->error, y_high = ymax->error;
    }
    const LogAxis x = axis_around(x_low, x_high), y = axis_around(y_low, y_high);
    const double plot_w = kWidth - kLeft - kRight, plot_h = kHeight - kTop - kBottom;

    std::string svg =
        format("<svg xmlns='http://www.w3.org/2000/svg' width='%.0f' height='%.0f' ", kWidth, kHeight) +
        "font-family='sans-serif' font-size='12'>\n<rect width='100%' height='100%' fill='white'/>\n";
    svg += format("<text x='%.1f' y='22' text-anchor='middle' font-size='15'>", kLeft + plot_w / 2) +
           escape(labels.title) + "</text>\n";
    svg += grid(x, y);
    svg += format("<text x='%.1f' y='%.1f' text-anchor='middle'>", kLeft + plot_w / 2, kHeight - 10) +
           escape(labels.x_axis) + "</text>\n";
    svg +=
        format("<text transform='translate(16,%.1f) rotate(-90)' text-anchor='middle'>", kTop + plot_h / 2) +
        escape(labels.y_axis) + "</text>\n";

    std::map<std::string, std::size_t> colour_of, shape_of;
    for (const PlotPoint& p : shown) {
        colour_of.emplace(p.series, colour_of.size() % kColours.size());
        shape_of.emplace(p.group, shape_of.size() % 3);
    }
    for (const PlotPoint& p : shown) {
        const double px = kLeft + x.to_unit(p.seconds) * plot_w,
                     py = kTop + (1.0 - y.to_unit(p.error)) * plot_h;
        svg += marker(
            shape_of[p.group], px, py, kColours[colour_of[p.series]],
            escape(p.group + ", " + p.series) + format(": %.3g s, %.3g %%", p.seconds, p.error * 100.0));
    }
    double legend_y = kTop + 10;
    for (const auto& [series, colour] : colour_of) {
        svg += marker(0, kWidth - kRight + 20, legend_y, kColours[colour], escape(series));
        svg += format("<text x='%.1f' y='%.1f'>", kWidth - kRight + 30, legend_y + 4) + escape(series) +
               "</text>\n";
        legend_y += 18;
    }
    for (const auto& [group, shape] : shape_of) {
        svg += marker(shape, kWidth - kRight + 20, legend_y, "#555", escape(group));
        svg += format("<text x='%.1f' y='%.1f'>", kWidth - kRight + 30, legend_y + 4) + escape(group) +
               "</text>\n";
        legend_y += 18;
    }
    return svg + "</svg>\n";
}

}  // namespace rad
