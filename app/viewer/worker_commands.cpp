#include "viewer/worker_commands.hpp"

#include <algorithm>
#include <utility>

namespace rad {

namespace {

// A newer command replaces a waiting one of its kind, but for writes (each its own file) and edits (one
// per material).
bool replaces(const WorkerCommands::Command& newer, const WorkerCommands::Command& older) {
    if (newer.index() != older.index() || std::holds_alternative<WorkerCommands::Write>(newer)) return false;
    if (const auto* edit = std::get_if<WorkerCommands::MaterialEdit>(&newer))
        return std::get<WorkerCommands::MaterialEdit>(older).name == edit->name;
    return true;
}

}  // namespace

void WorkerCommands::add(Command command) {
    if (std::holds_alternative<Step>(command)) {
        add_steps(1);
        return;
    }
    // Started again should the new scene not open.
    if (std::holds_alternative<Rebuild>(command) && current_rebuild_ && !interrupted_rebuild_)
        interrupted_rebuild_ = current_rebuild_;
    if (std::holds_alternative<Reset>(command)) stop_stepping();
    std::erase_if(waiting_, [&](const Command& waiting) { return replaces(command, waiting); });
    waiting_.push_back(std::move(command));
}

void WorkerCommands::add_steps(std::size_t count) {
    steps_ += count;
}

void WorkerCommands::stop_stepping() {
    steps_ = 0;
    running_ = false;
}

std::optional<std::size_t> WorkerCommands::next() const {
    const auto earliest =
        std::min_element(waiting_.begin(), waiting_.end(),
                         [](const Command& a, const Command& b) { return a.index() < b.index(); });
    if (earliest != waiting_.end()) return static_cast<std::size_t>(earliest - waiting_.begin());
    if (can_step_ && (steps_ > 0 || running_)) return waiting_.size();
    return std::nullopt;
}

WorkerCommands::Command WorkerCommands::take_next() {
    const std::size_t at = next().value();
    if (at == waiting_.size()) {
        if (steps_ > 0) --steps_;
        return Step{};
    }
    Command command = std::move(waiting_[at]);
    waiting_.erase(waiting_.begin() + static_cast<std::ptrdiff_t>(at));
    if (const auto* rebuild = std::get_if<Rebuild>(&command)) current_rebuild_ = *rebuild;
    return command;
}

void WorkerCommands::end_job(bool completed) {
    if (current_rebuild_ && completed) interrupted_rebuild_.reset();
    current_rebuild_.reset();
}

bool WorkerCommands::restart_interrupted() {
    std::optional<Rebuild> interrupted = std::exchange(interrupted_rebuild_, std::nullopt);
    const bool newer_waits = std::any_of(waiting_.begin(), waiting_.end(), [](const Command& waiting) {
        return std::holds_alternative<Rebuild>(waiting);
    });
    if (!interrupted || newer_waits) return false;
    // Not through add(): the rebuild that failed cut nothing short.
    waiting_.push_back(std::move(*interrupted));
    return true;
}

}  // namespace rad
