#include "text/progress_bar.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <vector>

namespace rad {

namespace {

constexpr int kBarWidth = 30;
// On a terminal the bar is redrawn often and shown soon; in a log a line every few seconds is enough, and
// the first comes later so that short work leaves the log clean.
constexpr std::chrono::milliseconds kTerminalDelay(1000);
constexpr std::chrono::milliseconds kRedrawInterval(200);
constexpr std::chrono::milliseconds kLogDelay(2000);
constexpr std::chrono::milliseconds kLogInterval(5000);
// Off the terminal the progress is still read this often, to see stage changes and notes as they come.
constexpr std::chrono::milliseconds kLogPoll(200);
constexpr double kLongStageSeconds = 5.0;
constexpr double kEstimateShare = 0.03;
constexpr double kEstimateSeconds = 1.0;

std::string whole_seconds(double seconds) {
    std::ostringstream s;
    s << static_cast<long long>(std::llround(seconds)) << " s";
    return s.str();
}

std::string labelled(const std::string& stage, const std::string& text) {
    return stage.empty() ? text : stage + ": " + text;
}

double seconds_of(std::chrono::milliseconds d) {
    return std::chrono::duration<double>(d).count();
}

}  // namespace

std::string progress_line(const std::string& stage, double fraction, double elapsed_seconds, bool estimate) {
    fraction = std::clamp(fraction, 0.0, 1.0);
    const int filled = static_cast<int>(fraction * kBarWidth);
    std::ostringstream line;
    line << stage << " [" << std::string(static_cast<std::size_t>(filled), '#')
         << std::string(static_cast<std::size_t>(kBarWidth - filled), '.') << "] " << std::setw(3)
         << static_cast<int>(fraction * 100.0) << "%  " << whole_seconds(elapsed_seconds);
    if (estimate && fraction > 0.01 && fraction < 1.0) {
        line << ", about " << whole_seconds(elapsed_seconds * (1.0 - fraction) / fraction) << " left";
    }
    return line.str();
}

bool progress_estimate_known(double fraction, double elapsed_seconds) {
    return fraction > 0.0 && fraction < 1.0 &&
           (fraction >= kEstimateShare || elapsed_seconds >= kEstimateSeconds);
}

std::string progress_log_line(const ProgressState& state, double elapsed_seconds) {
    std::ostringstream line;
    if (state.share_known()) {
        const double fraction = state.fraction();
        // The epsilon keeps 420 of 1000 at 42 %, not 41 from rounding below.
        line << static_cast<int>(fraction * 100.0 + 1e-9) << " % after " << whole_seconds(elapsed_seconds);
        if (progress_estimate_known(fraction, elapsed_seconds)) {
            line << ", about " << whole_seconds(elapsed_seconds * (1.0 - fraction) / fraction) << " left";
        }
    } else if (state.total > 0) {
        line << state.done << " of at most " << state.total << " after " << whole_seconds(elapsed_seconds);
    } else {
        line << "running for " << whole_seconds(elapsed_seconds);
    }
    return labelled(state.stage, line.str());
}

ProgressPrinter::ProgressPrinter(std::ostream& out, bool terminal, ProgressTiming timing)
    : out_(out), terminal_(terminal), timing_(timing), last_line_(timing.delay - timing.interval) {}

void ProgressPrinter::update(const Progress& progress, double seconds) {
    const ProgressState state = progress.state();
    if (state.stage_number == 0) return;  // nothing has begun
    if (!has_stage_ || state.stage_number != stage_number_) {
        if (has_stage_) end_stage(seconds);
        has_stage_ = true;
        stage_number_ = state.stage_number;
        stage_ = state.stage;
        stage_start_ = seconds;
        stage_reported_ = false;
        estimate_decided_ = false;
    }
    if (seconds < timing_.delay) return;
    started_ = true;
    print_notes(progress, state.notes);

    const double elapsed = seconds - stage_start_;
    const double fraction = state.fraction();
    // The first estimate decides, once: a stage that looks short then does not announce itself later.
    if (!estimate_decided_ && state.share_known() && progress_estimate_known(fraction, elapsed)) {
        estimate_decided_ = true;
        const double in_all = elapsed / fraction;
        if (in_all > timing_.long_stage)
            print_line(labelled(stage_, "estimated " + whole_seconds(in_all) + " in all"));
    }

    if (terminal_) {
        // \x1b[K clears what a longer previous line left at the end.
        out_ << '\r' << progress_line(stage_, fraction, elapsed, state.share_known()) << "\x1b[K"
             << std::flush;
        bar_drawn_ = true;
        return;
    }
    // A stage just begun waits a little for a share worth printing, but never more than two intervals.
    const double since_line = seconds - last_line_;
    const double grace = std::min(timing_.delay, timing_.interval);
    if (since_line >= timing_.interval && (elapsed >= grace || since_line >= 2.0 * timing_.interval)) {
        print_line(progress_log_line(state, elapsed));
        last_line_ = seconds;
        stage_reported_ = true;
    }
}

void ProgressPrinter::finish(double seconds) {
    if (terminal_) {
        if (bar_drawn_)
            out_ << "\r\x1b[K" << std::flush;  // erase the bar: what follows starts on a clean line
        bar_drawn_ = false;
        return;
    }
    if (has_stage_) end_stage(seconds);
    has_stage_ = false;
}

void ProgressPrinter::end_stage(double seconds) {
    if (terminal_ || !started_) return;
    const double ran = seconds - stage_start_;
    if (!stage_reported_ && ran < timing_.interval) return;
    print_line(labelled(stage_, "done in " + whole_seconds(ran)));
    last_line_ = seconds;
}

void ProgressPrinter::print_line(const std::string& line) {
    if (bar_drawn_) out_ << "\r\x1b[K";  // the line takes the bar's place; the bar is drawn again below it
    bar_drawn_ = false;
    out_ << "radiosity: " << line << '\n' << std::flush;
}

void ProgressPrinter::print_notes(const Progress& progress, std::size_t count) {
    if (count <= notes_shown_) return;
    const std::vector<ProgressNote> notes = progress.notes(notes_shown_);
    for (const ProgressNote& note : notes) print_line(labelled(note.stage, note.text));
    notes_shown_ += notes.size();
}

ProgressBar::ProgressBar(const Progress& progress)
    : ProgressBar(progress, std::cerr, ::isatty(STDERR_FILENO) == 1) {}

ProgressBar::ProgressBar(const Progress& progress, std::ostream& out, bool terminal)
    : ProgressBar(progress, out, terminal, terminal ? kTerminalDelay : kLogDelay,
                  terminal ? kRedrawInterval : kLogInterval) {}

ProgressBar::ProgressBar(const Progress& progress, std::ostream& out, bool terminal,
                         std::chrono::milliseconds delay, std::chrono::milliseconds interval)
    : progress_(progress),
      printer_(out, terminal, ProgressTiming{seconds_of(delay), seconds_of(interval), kLongStageSeconds}),
      poll_(std::max(std::chrono::milliseconds(1), terminal ? interval : std::min(interval, kLogPoll))) {
    thread_ = std::thread([this] { run(); });
}

ProgressBar::~ProgressBar() {
    {
        std::lock_guard lock(mutex_);
        stopping_ = true;
    }
    wake_.notify_all();
    thread_.join();
    printer_.finish(seconds());
}

double ProgressBar::seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void ProgressBar::run() {
    std::unique_lock lock(mutex_);
    while (!wake_.wait_for(lock, poll_, [this] { return stopping_; })) printer_.update(progress_, seconds());
}

}  // namespace rad
