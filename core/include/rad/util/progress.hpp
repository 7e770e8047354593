#pragma once

#include <atomic>
#include <cstdint>
#include <mutex>
#include <string>

namespace rad {

// Progress of long work (meshing, form factors, solving): the worker writes it, any thread reads it (the
// terminal's progress bar, the viewer's panel) and may ask the worker to stop. Thread-safe.
class Progress {
  public:
    void begin(const std::string& stage, std::uint64_t total) {
        {
            std::lock_guard lock(mutex_);
            stage_ = stage;
        }
        done_ = 0;
        total_ = total;
    }
    void advance(std::uint64_t amount = 1) { done_ += amount; }

    std::string stage() const {
        std::lock_guard lock(mutex_);
        return stage_;
    }
    double fraction() const {
        const std::uint64_t total = total_;
        return total == 0 ? 0.0 : static_cast<double>(done_.load()) / static_cast<double>(total);
    }

    void cancel() { cancelled_ = true; }
    bool cancelled() const { return cancelled_; }

  private:
    mutable std::mutex mutex_;
    std::string stage_;
    std::atomic<std::uint64_t> done_{0};
    std::atomic<std::uint64_t> total_{0};
    std::atomic<bool> cancelled_{false};
};

// Thrown by long work that saw Progress::cancelled().
struct Cancelled {};

}  // namespace rad
