#pragma once

// Strata an edge crosses, told from their neighbours. Private to the library.

#include <utility>

namespace rad {

// Whether stratum (x, y) of a side x side grid lies where `has(x, y)` changes (a ray reaches the sky or does
// not): some of its four neighbours have it and some do not. It looks only at the neighbours, never at the
// stratum itself, so the stratum's own sample, where it is kept, stays unbiased.
template <class Has>
bool neighbours_disagree(int x, int y, int side, const Has& has) {
    int seen = 0, with = 0;
    for (const auto& [dx, dy] : {std::pair{-1, 0}, std::pair{1, 0}, std::pair{0, -1}, std::pair{0, 1}}) {
        if (x + dx < 0 || x + dx >= side || y + dy < 0 || y + dy >= side) continue;
        ++seen;
        with += has(x + dx, y + dy) ? 1 : 0;
    }
    return with > 0 && with < seen;
}

}  // namespace rad
