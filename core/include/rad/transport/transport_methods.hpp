#pragma once

// The table of transport methods: every way of building light transport over a meshed scene is one entry,
// and everything outside a method's own folder asks the entry (or the transport it built) rather than which
// method it is. Adding a method is its folder plus one entry in transport_methods.cpp.

#include <cstddef>
#include <limits>
#include <span>
#include <string_view>
#include <vector>

namespace rad {

struct Scene;
struct PatchMesh;
struct SceneTransport;
struct TransportSettings;
class Progress;

// The methods by name, for code and files that name one; `automatic` is no method but the request to choose
// one (automatic_transport_method, choose_subdivision).
enum class Subdivision { automatic, uniform, adaptive, hierarchical, clustered };

// Builds the method's transport over `base`, meshed at the method's base_patch_scale. Throws InputError for
// bad settings or a pass over the memory budget, and Cancelled when `progress` is cancelled.
using BuildTransport = SceneTransport (*)(const Scene& scene, const PatchMesh& base,
                                          const TransportSettings& settings, Progress* progress);

// `auto` takes uniform patches up to this many at their default size, clustering beyond: below it uniform
// patches reach a given error sooner, above it clustering does (docs/measurements.md, "Scaling").
inline constexpr std::size_t kAutomaticUniformPatches = 10'000;

inline constexpr std::size_t kAnySize = std::numeric_limits<std::size_t>::max();

struct TransportMethod {
    Subdivision id;
    std::string_view name;  // as --subdivision, saved files and reports spell it
    std::string_view help;  // what it does, in a few words, for --subdivision's help
    // Its first or base patches, without --patch-size, as a multiple of the scene's uniform default size.
    double base_patch_scale = 1.0;
    // A form-factor matrix, which every solver can use; else links, which only the bounce solvers can.
    bool has_matrix = false;
    // Its elements are drawn on patches of the uniform size its base patches were scaled from (their light
    // comes from links to larger elements), rather than on the elements themselves.
    bool drawn_on_uniform_patches = false;
    // `auto` takes the first method in the table whose limit the scene's patch count at the uniform size is
    // within; 0: never chosen by `auto`.
    std::size_t automatic_up_to = 0;
    // Past this many base patches its first pass takes too long to be worth trying (every pair of base
    // patches is linked first); kAnySize: no such bound.
    std::size_t practical_base_patches = kAnySize;
    // The --refine-tol values worth comparing, coarse to fine (the bench sweeps them), and a coarse one for a
    // quick look; empty and 0 for a method that does not refine its elements.
    std::span<const double> refine_tolerances{};
    double quick_refine_tolerance = 0.0;
    BuildTransport build = nullptr;
};

// Every method, in the order `auto` tries them and lists show them.
std::span<const TransportMethod> transport_methods();

// The entry of a method; `automatic` must be chosen first (choose_subdivision).
const TransportMethod& transport_method(Subdivision id);
// The entry named `name`, or nullptr.
const TransportMethod* find_transport_method(std::string_view name);

// What `auto` picks for a scene of `uniform_patches` patches at the uniform default size.
const TransportMethod& automatic_transport_method(std::size_t uniform_patches);

// "auto", then each method's name.
std::string_view subdivision_name(Subdivision subdivision);
const std::vector<Subdivision>& all_subdivisions();  // automatic first

// What `automatic` means for a scene whose uniform mesh has `uniform_patches` patches; any other
// subdivision is itself.
Subdivision choose_subdivision(Subdivision requested, std::size_t uniform_patches);

// Whether that subdivision's transport has a form-factor matrix (see check_solver_supported); automatic
// must be chosen first (false).
bool has_matrix(Subdivision subdivision);

}  // namespace rad
