#pragma once

#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <mutex>
#include <ostream>
#include <string>
#include <thread>

#include "rad/util/progress.hpp"

namespace rad {

// When ProgressPrinter speaks, in seconds of work.
struct ProgressTiming {
    double delay = 2.0;       // nothing is shown before, so short work stays silent
    double interval = 5.0;    // between plain lines (off the terminal)
    double long_stage = 5.0;  // a stage estimated to take longer has its estimate printed once
};

// What ProgressBar shows, without a thread or a clock: update() reads the progress at `seconds` since the
// work began and writes what is due, so tests drive it with made-up times.
//
// On a terminal: a bar redrawn in place on one line (carriage return and erase-line codes). Off it (a log
// file, CI, a pipe): plain lines, "radiosity: form factors: 42 % after 12 s, about 17 s left", every
// `interval`, and "radiosity: form factors: done in 29 s" when a reported stage ends. Both print the notes
// once ("radiosity: form factors: 2516 patches × 2048 rays, about 11 MB") and, for a long stage, its
// estimate once it is known ("radiosity: form factors: estimated 29 s in all").
class ProgressPrinter {
  public:
    ProgressPrinter(std::ostream& out, bool terminal, ProgressTiming timing);
    void update(const Progress& progress, double seconds);
    // The work is over: erases the bar, or ends the last stage's lines.
    void finish(double seconds);

  private:
    void end_stage(double seconds);
    void print_line(const std::string& line);
    void print_notes(const Progress& progress, std::size_t count);

    std::ostream& out_;
    const bool terminal_;
    const ProgressTiming timing_;
    bool started_ = false;  // the delay has passed: output may appear
    bool bar_drawn_ = false;
    std::size_t notes_shown_ = 0;
    // The current stage.
    bool has_stage_ = false;
    std::uint64_t stage_number_ = 0;
    std::string stage_;
    double stage_start_ = 0.0;
    bool stage_reported_ = false;
    bool estimate_decided_ = false;
    double last_line_;  // when the last plain line was printed
};

// Shows a Progress on stderr while it lives: a thread polls the progress a few times a second and hands it
// to a ProgressPrinter (a bar on a terminal, plain lines otherwise). The destructor erases the bar, or
// prints the last stage's end.
class ProgressBar {
  public:
    explicit ProgressBar(const Progress& progress);
    // Writes to `out`, as on a terminal when `terminal` is true (for tests); `interval` is the terminal's
    // redraw period or the plain lines' period.
    ProgressBar(const Progress& progress, std::ostream& out, bool terminal, std::chrono::milliseconds delay,
                std::chrono::milliseconds interval);
    ~ProgressBar();
    ProgressBar(const ProgressBar&) = delete;
    ProgressBar& operator=(const ProgressBar&) = delete;

  private:
    ProgressBar(const Progress& progress, std::ostream& out, bool terminal);  // the default timing
    void run();
    double seconds() const;

    const Progress& progress_;
    ProgressPrinter printer_;
    const std::chrono::milliseconds poll_;
    const std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
    std::mutex mutex_;
    std::condition_variable wake_;
    bool stopping_ = false;
    std::thread thread_;
};

// "form factors [##########..........]  50%  12 s, about 12 s left": one line, no line break; without
// `estimate`, no time left.
std::string progress_line(const std::string& stage, double fraction, double elapsed_seconds,
                          bool estimate = true);

// "form factors: 42 % after 12 s, about 17 s left" (the time left once the estimate is known), "solving: 30
// of at most 1000 after 12 s", or "linking elements: running for 12 s" when the total is not known.
std::string progress_log_line(const ProgressState& state, double elapsed_seconds);

// Whether the time left can be estimated: after the first few per cent of the work, or a second.
bool progress_estimate_known(double fraction, double elapsed_seconds);

}  // namespace rad
