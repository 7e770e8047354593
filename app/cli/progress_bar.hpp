#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <mutex>
#include <ostream>
#include <string>
#include <thread>

#include "rad/util/progress.hpp"

namespace rad {

// Shows a Progress as a bar on the terminal while it lives: a thread polls the progress a few times a
// second and redraws one line on stderr, but only when stderr is a terminal and the work has run longer
// than `delay`, so short work and redirected output stay clean. The destructor erases the line.
class ProgressBar {
  public:
    explicit ProgressBar(const Progress& progress, std::chrono::milliseconds delay = std::chrono::seconds(1));
    // Draws to `out` as if it were a terminal when `terminal` is true (for tests).
    ProgressBar(const Progress& progress, std::ostream& out, bool terminal, std::chrono::milliseconds delay,
                std::chrono::milliseconds interval);
    ~ProgressBar();
    ProgressBar(const ProgressBar&) = delete;
    ProgressBar& operator=(const ProgressBar&) = delete;

  private:
    void run();
    void draw(std::chrono::steady_clock::duration elapsed);

    const Progress& progress_;
    std::ostream& out_;
    const bool terminal_;
    const std::chrono::milliseconds delay_;
    const std::chrono::milliseconds interval_;
    const std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
    std::mutex mutex_;
    std::condition_variable wake_;
    bool stopping_ = false;
    bool drawn_ = false;
    std::thread thread_;
};

// "form factors [##########..........]  50%  12 s, about 12 s left": one line, no line break.
std::string progress_line(const std::string& stage, double fraction, double elapsed_seconds);

}  // namespace rad
