#include "cli/progress_bar.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace rad {

namespace {

constexpr int kBarWidth = 30;
constexpr std::chrono::milliseconds kRedrawInterval(200);

std::string whole_seconds(double seconds) {
    std::ostringstream s;
    s << static_cast<long long>(std::llround(seconds)) << " s";
    return s.str();
}

}  // namespace

std::string progress_line(const std::string& stage, double fraction, double elapsed_seconds) {
    fraction = std::clamp(fraction, 0.0, 1.0);
    const int filled = static_cast<int>(fraction * kBarWidth);
    std::ostringstream line;
    line << stage << " [" << std::string(static_cast<std::size_t>(filled), '#')
         << std::string(static_cast<std::size_t>(kBarWidth - filled), '.') << "] " << std::setw(3)
         << static_cast<int>(fraction * 100.0) << "%  " << whole_seconds(elapsed_seconds);
    if (fraction > 0.01 && fraction < 1.0) {
        line << ", about " << whole_seconds(elapsed_seconds * (1.0 - fraction) / fraction) << " left";
    }
    return line.str();
}

ProgressBar::ProgressBar(const Progress& progress, std::chrono::milliseconds delay)
    : ProgressBar(progress, std::cerr, ::isatty(STDERR_FILENO) == 1, delay, kRedrawInterval) {}

ProgressBar::ProgressBar(const Progress& progress, std::ostream& out, bool terminal,
                         std::chrono::milliseconds delay, std::chrono::milliseconds interval)
    : progress_(progress), out_(out), terminal_(terminal), delay_(delay), interval_(interval) {
    if (terminal_) thread_ = std::thread([this] { run(); });
}

ProgressBar::~ProgressBar() {
    if (!thread_.joinable()) return;
    {
        std::lock_guard lock(mutex_);
        stopping_ = true;
    }
    wake_.notify_all();
    thread_.join();
    if (drawn_) out_ << "\r\x1b[K" << std::flush;  // erase the bar: what follows starts on a clean line
}

void ProgressBar::run() {
    std::unique_lock lock(mutex_);
    while (!wake_.wait_for(lock, interval_, [this] { return stopping_; })) {
        const auto elapsed = std::chrono::steady_clock::now() - start_;
        if (elapsed >= delay_) draw(elapsed);
    }
}

void ProgressBar::draw(std::chrono::steady_clock::duration elapsed) {
    const double seconds = std::chrono::duration<double>(elapsed).count();
    // \x1b[K clears what a longer previous line left at the end.
    out_ << '\r' << progress_line(progress_.stage(), progress_.fraction(), seconds) << "\x1b[K" << std::flush;
    drawn_ = true;
}

}  // namespace rad
