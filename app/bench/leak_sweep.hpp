#pragma once

#include <functional>
#include <string>
#include <vector>

#include "rad/reference/leak_rooms.hpp"
#include "rad/transport/scene_transport.hpp"

namespace rad {

// `radiosity bench --leaks`: the leak suite's rooms (rad/reference/leak_rooms.hpp), each solved at the
// defaults with every subdivision, and the light found in its closed interior: on the elements and in an
// image rendered from inside.
struct LeakPlan {
    std::string folder = "assets/hard";  // where the rooms' OBJ files are
    int image_size = 128;
};

struct LeakRow {
    std::string room;
    std::string subdivision;
    std::size_t elements = 0;
    std::size_t inside = 0;     // elements looking into the interior
    double element_leak = 0.0;  // worst inside element / the lit elements' mean
    double image_leak = 0.0;    // brightest pixel seen from inside, as radiosity, / the same mean
    double energy_error = 0.0;  // |emitted + outside − absorbed − escaped| / (emitted + outside)
    double seconds = 0.0;
    std::string failure;  // why the run stopped, or empty
};

// Throws InputError naming the folder when a room's file is missing, before any work.
void check_leak_plan(const LeakPlan& plan);

// One room solved at the defaults with one subdivision, measured. Needs a current OpenGL context.
LeakRow run_leak_room(const LeakPlan& plan, const LeakRoom& room, Subdivision subdivision);

// Runs every room with every subdivision; `log` sees one line per run. Needs a current OpenGL context.
std::vector<LeakRow> run_leaks(const LeakPlan& plan, const std::function<void(const std::string&)>& log);

std::string leak_table(const std::vector<LeakRow>& rows);
std::string leak_csv(const std::vector<LeakRow>& rows);

}  // namespace rad
