#pragma once

#include <algorithm>
#include <cstddef>

namespace rad {

// Frame durations for the panel and for checking that the window stays responsive while work runs: the
// latest, a running mean, the longest, and the longest seen while the worker was busy (the figure that must
// stay short). That last one leaves out the first frames: a driver compiles shaders at their first use
// (llvmpipe takes 50-60 ms for each program), once, whether or not any background work runs.
class FrameTimer {
  public:
    static constexpr std::size_t kWarmUpFrames = 3;

    void add(double seconds, bool worker_busy) {
        latest_ = seconds;
        mean_ = count_ == 0 ? seconds : mean_ + (seconds - mean_) * 0.05;  // about the last 20 frames
        ++count_;
        longest_ = std::max(longest_, seconds);
        if (worker_busy && count_ > kWarmUpFrames)
            longest_while_busy_ = std::max(longest_while_busy_, seconds);
    }
    double latest() const { return latest_; }
    double mean() const { return mean_; }
    double longest() const { return longest_; }
    double longest_while_busy() const { return longest_while_busy_; }
    // From a key or button press arriving to the end of the frame that drew its effect (the swap), which is
    // what a person waits for but the display's own delay.
    void add_input_latency(double seconds, bool worker_busy) {
        latest_input_ = seconds;
        longest_input_ = std::max(longest_input_, seconds);
        if (worker_busy) longest_input_while_busy_ = std::max(longest_input_while_busy_, seconds);
        ++inputs_;
    }
    double latest_input_latency() const { return latest_input_; }
    double longest_input_latency() const { return longest_input_; }
    double longest_input_latency_while_busy() const { return longest_input_while_busy_; }
    std::size_t inputs() const { return inputs_; }
    std::size_t count() const { return count_; }

  private:
    double latest_ = 0.0;
    double mean_ = 0.0;
    double longest_ = 0.0;
    double longest_while_busy_ = 0.0;
    std::size_t count_ = 0;
    double latest_input_ = 0.0;
    double longest_input_ = 0.0;
    double longest_input_while_busy_ = 0.0;
    std::size_t inputs_ = 0;
};

}  // namespace rad
